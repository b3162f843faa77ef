#include "materials/material_plugins.h"

#include "materials/disney.h"
#include "materials/fourier.h"
#include "materials/glass.h"
#include "materials/hair.h"
#include "materials/lafortune_material.h"
#include "materials/matte.h"
#include "materials/measured.h"
#include "materials/metal.h"
#include "materials/mirror.h"
#include "materials/mix.h"
#include "materials/plastic.h"
#include "materials/shinymetal.h"
#include "materials/substrate.h"
#include "materials/subsurface.h"
#include "materials/translucent.h"
#include "materials/uber.h"

namespace candela {

namespace {

constexpr std::string_view kSpec = "spectrum texture";
constexpr std::string_view kFloat = "float texture";
constexpr std::string_view kUnit = "within [0, 1]";

// Every material but mix and hair takes one.
constexpr ParamSpec kBump{
    "bumpmap", kFloat, "(none)", "", "", kAllDialects, "height field for bump mapping"};
// pbrt-v3's microfacet models (parser/scene_dialect.h chooses them).
constexpr ParamSpec kRemap{"remaproughness",
                           "bool",
                           "true",
                           "",
                           "",
                           kPbrtV3,
                           "roughness is mapped to the microfacet alpha"};

constexpr ParamSpec kMatte[] = {
    {"Kd", kSpec, "0.5", "", "", kAllDialects, "diffuse reflectance"},
    {"sigma", kFloat, "0", "", "", kAllDialects, "Oren-Nayar roughness, degrees (0: Lambertian)"},
    kBump};
constexpr ParamSpec kPlastic[] = {
    {"Kd", kSpec, "0.25", "", "", kAllDialects, "diffuse reflectance"},
    {"Ks", kSpec, "0.25", "", "", kAllDialects, "glossy coat reflectance"},
    {"roughness", kFloat, "0.1", "", "", kAllDialects, "coat roughness"},
    kRemap,
    kBump};
constexpr ParamSpec kTranslucent[] = {
    {"Kd", kSpec, "0.25", "", "", kAllDialects, "diffuse coefficient"},
    {"Ks", kSpec, "0.25", "", "", kAllDialects, "glossy coefficient"},
    {"reflect", kSpec, "0.5", "", "", kAllDialects, "fraction reflected"},
    {"transmit", kSpec, "0.5", "", "", kAllDialects, "fraction transmitted"},
    {"roughness", kFloat, "0.1", "", "", kAllDialects, "glossy roughness"},
    {"index", "float", "1.5", "", "", kAllDialects, "index of refraction"},
    kRemap,
    kBump};
constexpr ParamSpec kGlass[] = {
    {"Kr", kSpec, "1", "", "", kAllDialects, "reflection scale"},
    {"Kt", kSpec, "1", "", "", kAllDialects, "transmission scale"},
    {"index", kFloat, "1.5", "", "", kAllDialects, "index of refraction"},
    {"eta", kFloat, "(index)", "", "", kPbrtV3, "index of refraction (pbrt-v3's name)"},
    {"uroughness", kFloat, "0", "", "", kPbrtV3, "roughness along u (0: smooth)"},
    {"vroughness", kFloat, "0", "", "", kPbrtV3, "roughness along v (0: smooth)"},
    kRemap,
    kBump};
constexpr ParamSpec kMirror[] = {{"Kr", kSpec, "0.9", "", "", kAllDialects, "reflectance"}, kBump};
constexpr ParamSpec kMetal[] = {
    {"eta", kSpec, "(copper)", "", "", kPbrt, "index of refraction"},
    {"k", kSpec, "(copper)", "", "", kPbrt, "absorption coefficient"},
    {"roughness", kFloat, "0.01", "", "", kPbrt, "microfacet roughness"},
    {"uroughness", kFloat, "(roughness)", "", "", kPbrtV3, "roughness along u"},
    {"vroughness", kFloat, "(roughness)", "", "", kPbrtV3, "roughness along v"},
    kRemap,
    kBump};
constexpr ParamSpec kShinyMetal[] = {
    {"Ks", kSpec, "1", "", "", kLrt | kPbrtV2, "glossy reflectance"},
    {"Kr", kSpec, "1", "", "", kLrt | kPbrtV2, "specular reflectance"},
    {"roughness", kFloat, "0.1", "", "", kLrt | kPbrtV2, "glossy roughness"},
    kBump};
constexpr ParamSpec kSubstrate[] = {
    {"Kd", kSpec, "0.5", "", "", kPbrt, "diffuse base reflectance"},
    {"Ks", kSpec, "0.5", "", "", kPbrt, "glossy coat reflectance at normal incidence"},
    {"uroughness", kFloat, "0.1", "", "", kPbrt, "roughness along u"},
    {"vroughness", kFloat, "0.1", "", "", kPbrt, "roughness along v"},
    kRemap,
    kBump};
constexpr ParamSpec kUber[] = {
    {"Kd", kSpec, "0.25", "", "", kPbrt, "diffuse reflectance"},
    {"Ks", kSpec, "0.25", "", "", kPbrt, "glossy reflectance"},
    {"Kr", kSpec, "0", "", "", kPbrt, "specular reflectance"},
    {"Kt", kSpec, "0", "", "", kPbrtV3, "specular transmittance"},
    {"opacity", kSpec, "1", "", "", kPbrt, "opacity (1 - straight-through transmission)"},
    {"roughness", kFloat, "0.1", "", "", kPbrt, "glossy roughness"},
    {"uroughness", kFloat, "(roughness)", "", "", kPbrtV3, "roughness along u"},
    {"vroughness", kFloat, "(uroughness)", "", "", kPbrtV3, "roughness along v"},
    {"index", kFloat, "1.5", "", "", kPbrt, "index of refraction"},
    {"eta", kFloat, "(index)", "", "", kPbrtV3, "index of refraction (pbrt-v3's name)"},
    kRemap,
    kBump};
constexpr ParamSpec kMix[] = {
    {"amount", kSpec, "0.5", "", "", kPbrt, "weight of namedmaterial2"},
    {"namedmaterial1", "string", "(required)", "", "", kPbrt, "a MakeNamedMaterial name"},
    {"namedmaterial2", "string", "(required)", "", "", kPbrt, "a MakeNamedMaterial name"}};
constexpr ParamSpec kMeasured[] = {{"filename", "string", "(required)", "", "", kPbrtV2,
                                    "MERL binary table or irregular (Marschner) sample file"},
                                   kBump};
constexpr ParamSpec kFourier[] = {
    {"bsdffile", "string", "(required)", "", "", kPbrtV3, "pbrt-v3 Fourier BSDF file"}, kBump};
constexpr ParamSpec kClay[] = {kBump};
constexpr ParamSpec kSubsurface[] = {
    {"name", "string", "(none)", "", "", kPbrt, "a measured medium (Jensen et al. 2001)"},
    {"sigma_a", kSpec, "(whole milk)", "", "non-negative and finite", kPbrt,
     "absorption, per mm times scale"},
    {"sigma_prime_s", kSpec, "(whole milk)", "", "non-negative and finite", kPbrt,
     "reduced scattering, per mm times scale"},
    {"scale", "float", "1", "", "positive and finite", kPbrt, "scene units per mm"},
    {"index", "float", "1.33", "", "positive and finite", kPbrt, "index of refraction"},
    {"Kr", kSpec, "1", "", "", kPbrt, "specular reflection scale"},
    kBump};
constexpr ParamSpec kKdSubsurface[] = {
    {"Kd", kSpec, "0.5", "", "", kPbrt, "diffuse reflectance the medium is fitted to"},
    {"meanfreepath", kFloat, "1", "", "positive and finite", kPbrt, "mean free path"},
    {"index", "float", "1.33", "", "positive and finite", kPbrt, "index of refraction"},
    {"Kr", kSpec, "1", "", "", kPbrt, "specular reflection scale"},
    kBump};
constexpr ParamSpec kDisney[] = {
    {"color", kSpec, "0.5", "", "at least 0", kPbrtV3, "base colour"},
    {"metallic", kFloat, "0", "", kUnit, kPbrtV3, "metal blend"},
    {"eta", kFloat, "1.5", "", "positive and finite", kPbrtV3, "index of refraction"},
    {"roughness", kFloat, "0.5", "", kUnit, kPbrtV3, "specular roughness"},
    {"speculartint", kFloat, "0", "", kUnit, kPbrtV3, "tint of the specular lobe"},
    {"anisotropic", kFloat, "0", "", kUnit, kPbrtV3, "specular anisotropy"},
    {"sheen", kFloat, "0", "", kUnit, kPbrtV3, "sheen weight"},
    {"sheentint", kFloat, "0.5", "", kUnit, kPbrtV3, "tint of the sheen"},
    {"clearcoat", kFloat, "0", "", kUnit, kPbrtV3, "clear coat weight"},
    {"clearcoatgloss", kFloat, "1", "", kUnit, kPbrtV3, "clear coat gloss"},
    {"spectrans", kFloat, "0", "", kUnit, kPbrtV3, "specular transmission weight"},
    {"flatness", kFloat, "0", "", kUnit, kPbrtV3, "thin surfaces: fake subsurface blend"},
    {"difftrans", kFloat, "1", "", "within [0, 2]", kPbrtV3, "thin surfaces: diffuse transmission"},
    {"thin", "bool", "false", "", "", kPbrtV3, "a thin sheet instead of a solid"},
    {"scatterdistance", kSpec, "0", "", "at least 0", kPbrtV3,
     "subsurface distance (not implemented: warned)"},
    kBump};
constexpr ParamSpec kHair[] = {
    {"sigma_a", kSpec, "(none)", "", "non-negative and finite", kPbrtV3,
     "absorption per unit fibre radius (first choice)"},
    {"color", kSpec, "(none)", "", kUnit, kPbrtV3, "fibre colour (second choice)"},
    {"eumelanin", kFloat, "1.3", "", "non-negative and finite", kPbrtV3,
     "eumelanin concentration (third choice)"},
    {"pheomelanin", kFloat, "0", "", "non-negative and finite", kPbrtV3,
     "pheomelanin concentration"},
    {"eta", kFloat, "1.55", "", "at least 1", kPbrtV3, "index of refraction of the fibre"},
    {"beta_m", kFloat, "0.3", "", "within (0, 1]", kPbrtV3, "longitudinal roughness"},
    {"beta_n", kFloat, "0.3", "", "within (0, 1]", kPbrtV3, "azimuthal roughness"},
    {"alpha", kFloat, "2", "", "finite", kPbrtV3, "scale tilt, degrees"}};

constexpr MaterialPlugin kMaterials[] = {
    {{"material", "matte", kAllDialects, "Lambertian or Oren-Nayar diffuse (lrt draft §10.2)",
      kMatte},
     createMatteMaterial},
    {{"material", "plastic", kAllDialects,
      "diffuse base under a glossy coat (lrt draft §10.3; pbrt 3e §9.2.2)", kPlastic},
     createPlasticMaterial},
    {{"material", "translucent", kAllDialects,
      "diffuse and glossy reflection and transmission (lrt draft §10.4)", kTranslucent},
     createTranslucentMaterial},
    {{"material", "glass", kAllDialects,
      "specular (pbrt-v3: also rough) dielectric (lrt draft §10.6; pbrt 3e §9.2)", kGlass},
     createGlassMaterial},
    {{"material", "mirror", kAllDialects, "perfect specular reflector (lrt draft §10.5)", kMirror},
     createMirrorMaterial},
    {{"material", "metal", kPbrt, "conductor with microfacets (pbrt 2e §9.2; pbrt 3e §9.2)",
      kMetal},
     createMetalMaterial},
    {{"material", "shinymetal", kLrt | kPbrtV2,
      "glossy and specular metal from approximate eta (lrt draft §10.7)", kShinyMetal},
     createShinyMetalMaterial},
    {{"material", "substrate", kPbrt, "Ashikhmin-Shirley coated diffuse (pbrt 2e §9.2)",
      kSubstrate},
     createSubstrateMaterial},
    {{"material", "uber", kPbrt, "diffuse, glossy, specular and opacity in one (pbrt 2e §9.2)",
      kUber},
     createUberMaterial},
    {{"material", "mix", kPbrt, "blend of two named materials (pbrt 2e §9.2.2)", kMix},
     createMixMaterial},
    {{"material", "measured", kPbrtV2, "measured BRDF, MERL or irregular (pbrt 2e §8.6)",
      kMeasured},
     createMeasuredMaterial},
    {{"material", "fourier", kPbrtV3, "tabulated Fourier BSDF (pbrt 3e §8.6)", kFourier},
     createFourierMaterial},
    {{"material", "clay", kLrt, "lrt's measured Lafortune fit (lrt draft §10.9)", kClay},
     createClayMaterial},
    {{"material", "subsurface", kPbrt, "dipole subsurface scattering (pbrt 2e §16.5)", kSubsurface},
     createSubsurfaceMaterial},
    {{"material", "kdsubsurface", kPbrt,
      "dipole subsurface scattering fitted to a diffuse reflectance (pbrt 2e §16.5)",
      kKdSubsurface},
     createKdSubsurfaceMaterial},
    {{"material", "disney", kPbrtV3, "Disney's principled BSDF (Burley 2012, 2015)", kDisney},
     createDisneyMaterial},
    {{"material", "hair", kPbrtV3, "Chiang et al.'s hair scattering (pbrt 3e §9.4 online)", kHair},
     createHairMaterial},
};

}  // namespace

std::span<const MaterialPlugin> materialPlugins() { return kMaterials; }

}  // namespace candela
