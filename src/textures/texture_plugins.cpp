#include "textures/texture_plugins.h"

#include <type_traits>

#include "core/image_loader.h"
#include "core/scene_path.h"
#include "textures/basic_textures.h"
#include "textures/checkerboard.h"
#include "textures/dots.h"
#include "textures/image_texture.h"
#include "textures/solid_textures.h"
#include "textures/texture_params.h"

namespace candela {

namespace {

using Context = TextureInputs;

template <typename T>
T getOne(const ParamSet& params, const std::string& name, const T& def) {
  if constexpr (std::is_same_v<T, Float>)
    return params.getOneFloat(name, def);
  else
    return params.getOneSpectrum(name, def);
}

std::unique_ptr<TextureMapping2D> mapping2D(const Context& c) {
  return createMapping2D(c.params(), c.textureToWorld(), c.location());
}

// pbrt-v2 and v3 hand the CTM itself to the 3D mapping as its world-to-texture transform, so a
// Scale 3 before the Texture statement makes the pattern three times finer; scenes are written
// for that.
TextureMapping3D mapping3D(const Context& c) { return TextureMapping3D(c.textureToWorld()); }

template <typename T>
std::unique_ptr<Texture<T>> createConstant(Context& c) {
  return std::make_unique<ConstantTexture<T>>(getOne<T>(c.params(), "value", T(1)));
}

template <typename T>
std::unique_ptr<Texture<T>> createScale(Context& c) {
  return std::make_unique<ScaleTexture<T>>(c.texture<T>("tex1", T(1)), c.texture<T>("tex2", T(1)));
}

template <typename T>
std::unique_ptr<Texture<T>> createMix(Context& c) {
  const Texture<T>* t1 = c.texture<T>("tex1", T(0));
  const Texture<T>* t2 = c.texture<T>("tex2", T(1));
  return std::make_unique<MixTexture<T>>(t1, t2, c.texture<Float>("amount", 0.5f));
}

template <typename T>
std::unique_ptr<Texture<T>> createBilerp(Context& c) {
  const ParamSet& p = c.params();
  return std::make_unique<BilerpTexture<T>>(mapping2D(c), getOne<T>(p, "v00", T(0)),
                                            getOne<T>(p, "v01", T(1)), getOne<T>(p, "v10", T(0)),
                                            getOne<T>(p, "v11", T(1)));
}

std::unique_ptr<Texture<Spectrum>> createUV(Context& c) {
  return std::make_unique<UVTexture>(mapping2D(c));
}

template <typename T>
std::unique_ptr<Texture<T>> createCheckerboard(Context& c) {
  const ParamSet& p = c.params();
  const FileLoc& loc = c.location();
  int dimension = p.getOneInt("dimension", 2, ValueRange::within(2, 3), loc);
  std::string aa = p.getOneString("aamode", dimension == 2 ? "closedform" : "supersample",
                                  {"closedform", "supersample", "none"}, loc);
  const Texture<T>* t1 = c.texture<T>("tex1", T(1));
  const Texture<T>* t2 = c.texture<T>("tex2", T(0));
  if (dimension == 3)
    return std::make_unique<Checkerboard3DTexture<T>>(mapping3D(c), t1, t2, aa != "none");
  CheckerboardAA mode = aa == "none"          ? CheckerboardAA::None
                        : aa == "supersample" ? CheckerboardAA::Supersample
                                              : CheckerboardAA::ClosedForm;
  return std::make_unique<Checkerboard2DTexture<T>>(mapping2D(c), t1, t2, mode);
}

template <typename T>
std::unique_ptr<Texture<T>> createDots(Context& c) {
  // pbrt-v2 and v3 hand "inside" to the dots texture's outside slot and "outside" to its inside
  // (their constructor takes the two in the opposite order to their factory), so in every
  // pbrt scene the "inside" value fills the space between the dots. Files mean what pbrt shows.
  const Texture<T>* between = c.texture<T>("inside", T(1));
  const Texture<T>* dots = c.texture<T>("outside", T(0));
  return std::make_unique<DotsTexture<T>>(mapping2D(c), between, dots);
}

template <typename T>
std::unique_ptr<Texture<T>> createFBm(Context& c) {
  const ParamSet& p = c.params();
  return std::make_unique<FBmTexture<T>>(mapping3D(c), p.getOneInt("octaves", 8),
                                         p.getOneFloat("roughness", .5f));
}

template <typename T>
std::unique_ptr<Texture<T>> createWrinkled(Context& c) {
  const ParamSet& p = c.params();
  return std::make_unique<WrinkledTexture<T>>(mapping3D(c), p.getOneInt("octaves", 8),
                                              p.getOneFloat("roughness", .5f), c.clampedOctaves());
}

template <typename T>
std::unique_ptr<Texture<T>> createWindy(Context& c) {
  return std::make_unique<WindyTexture<T>>(mapping3D(c));
}

std::unique_ptr<Texture<Spectrum>> createMarble(Context& c) {
  const ParamSet& p = c.params();
  return std::make_unique<MarbleTexture>(mapping3D(c), p.getOneInt("octaves", 8),
                                         p.getOneFloat("roughness", .5f), p.getOneFloat("scale", 1),
                                         p.getOneFloat("variation", .2f));
}

template <typename T>
std::unique_ptr<Texture<T>> createImageMap(Context& c) {
  const ParamSet& p = c.params();
  // Every parameter is read before the file, so parameter errors come first.
  std::string filename = p.getOneString("filename", "");
  if (filename.empty())
    throw SceneError(c.location(),
                     "imagemap texture '" + c.textureName() + "' needs a \"string filename\"");
  std::string path = resolveScenePath(filename, p.locationOf("filename", c.location()).file);
  std::string colorSpace = p.getOneString("colorspace", "");
  std::string wrapName =
      p.getOneString("wrap", "repeat", {"repeat", "black", "clamp"}, c.location());
  WrapMode wrap = *parseWrapMode(wrapName);
  Float maxAnisotropy = p.getOneFloat("maxanisotropy", 8);
  bool trilinear = p.getOneBool("trilinear", false);
  Float scale = p.getOneFloat("scale", 1), gamma = 1;
  // "gamma" is pbrt-v3's bool (true: the numbers are sRGB-encoded, false: linear, whatever the
  // pixel type; absent, pbrt-v3 decodes PNG and TGA only, which the default rule does) or
  // pbrt-v2's float exponent applied after the scale. A "string colorspace" overrides the bool.
  if (const ParamItem* g = p.find("gamma")) {
    if (g->type == ParamType::Bool) {
      bool encoded = p.getOneBool("gamma", false);
      if (colorSpace.empty()) colorSpace = encoded ? kSrgbEncoded : kStoredLinear;
    } else {
      gamma = p.getOneFloat("gamma", 1);
    }
  }
  std::unique_ptr<TextureMapping2D> mapping = mapping2D(c);
  std::shared_ptr<const MIPMap<T>> mipmap = c.mipmap<T>(path, colorSpace, wrap, scale, gamma);
  return std::make_unique<ImageTexture<T>>(std::move(mapping), mipmap, trilinear, maxAnisotropy);
}

// Parameters whose type is the texture's own ("float" in a float texture, "spectrum" in a
// spectrum one) are typed "float or spectrum".
constexpr std::string_view kOwn = "float or spectrum";
constexpr std::string_view kOwnTexture = "float or spectrum texture";

// createMapping2D's parameters (textures/texture_params.cpp), shared by every 2D-mapped class:
// uscale..vdelta for "uv" (lrt's su..dv as their defaults), v1, v2, udelta, vdelta for "planar".
constexpr std::array<ParamSpec, 11> kMapping2D = {{
    {"mapping", "string", "uv", "", "one of uv, spherical, cylindrical, planar", kAllDialects,
     "(s, t) from the surface's (u, v), a sphere, a cylinder or a plane"},
    {"uscale", "float", "1", "", "", kAllDialects, "uv: s = uscale u + udelta (default su)"},
    {"vscale", "float", "1", "", "", kAllDialects, "uv: t = vscale v + vdelta (default sv)"},
    {"udelta", "float", "0", "", "", kAllDialects, "uv and planar: offset of s (default du)"},
    {"vdelta", "float", "0", "", "", kAllDialects, "uv and planar: offset of t (default dv)"},
    {"su", "float", "1", "", "", kLrt, "lrt's uscale"},
    {"sv", "float", "1", "", "", kLrt, "lrt's vscale"},
    {"du", "float", "0", "", "", kLrt, "lrt's udelta"},
    {"dv", "float", "0", "", "", kLrt, "lrt's vdelta"},
    {"v1", "vector3", "1 0 0", "", "", kAllDialects, "planar: the direction of s",
     "with \"mapping\" planar"},
    {"v2", "vector3", "0 1 0", "", "", kAllDialects, "planar: the direction of t",
     "with \"mapping\" planar"},
}};

constexpr ParamSpec kConstantParams[] = {
    {"value", kOwn, "1", "", "", kAllDialects, "the value everywhere"},
};

constexpr ParamSpec kScaleParams[] = {
    {"tex1", kOwnTexture, "1", "", "", kAllDialects, "first factor"},
    {"tex2", kOwnTexture, "1", "", "", kAllDialects, "second factor"},
};

constexpr ParamSpec kMixParams[] = {
    {"tex1", kOwnTexture, "0", "", "", kAllDialects, "value at amount 0"},
    {"tex2", kOwnTexture, "1", "", "", kAllDialects, "value at amount 1"},
    {"amount", "float texture", "0.5", "", "", kAllDialects, "blend weight (not clamped)"},
};

constexpr auto kBilerpParams =
    joinParams(kMapping2D, std::to_array<ParamSpec>({
                               {"v00", kOwn, "0", "", "", kAllDialects, "value at (s, t) = (0, 0)"},
                               {"v01", kOwn, "1", "", "", kAllDialects, "value at (0, 1)"},
                               {"v10", kOwn, "0", "", "", kAllDialects, "value at (1, 0)"},
                               {"v11", kOwn, "1", "", "", kAllDialects, "value at (1, 1)"},
                           }));

constexpr auto kUVParams = kMapping2D;

constexpr auto kCheckerboardParams = joinParams(
    kMapping2D,
    std::to_array<ParamSpec>({
        {"dimension", "integer", "2", "", "within [2, 3]", kAllDialects,
         "2: on (s, t); 3: solid, in texture space"},
        {"aamode", "string", "(closedform in 2D, supersample in 3D)", "",
         "one of closedform, supersample, none", kAllDialects, "antialiasing"},
        {"tex1", kOwnTexture, "1", "", "", kAllDialects, "where floor(s) + floor(t) is even"},
        {"tex2", kOwnTexture, "0", "", "", kAllDialects, "where it is odd"},
    }));

constexpr auto kDotsParams = joinParams(
    kMapping2D,
    std::to_array<ParamSpec>({
        {"inside", kOwnTexture, "1", "", "", kAllDialects,
         "fills the space between the dots, as pbrt shows it"},
        {"outside", kOwnTexture, "0", "", "", kAllDialects, "fills the dots, as pbrt shows it"},
    }));

constexpr ParamSpec kNoiseParams[] = {
    {"octaves", "integer", "8", "", "", kAllDialects, "noise octaves summed"},
    {"roughness", "float", "0.5", "", "", kAllDialects, "amplitude ratio of successive octaves"},
};

constexpr ParamSpec kMarbleParams[] = {
    {"octaves", "integer", "8", "", "", kAllDialects, "noise octaves summed"},
    {"roughness", "float", "0.5", "", "", kAllDialects, "amplitude ratio of successive octaves"},
    {"scale", "float", "1", "", "", kAllDialects, "frequency of the noise"},
    {"variation", "float", "0.2", "", "", kAllDialects, "strength of the veins' perturbation"},
};

constexpr auto kImageMapParams = joinParams(
    kMapping2D,
    std::to_array<ParamSpec>({
        {"filename", "string", "(required)", "", "", kAllDialects,
         "the image, relative to the scene file"},
        {"colorspace", "string", "(none)", "", "", kCandela,
         "the image's OCIO colour space (none: sRGB for integer pixels, linear for float)"},
        {"wrap", "string", "repeat", "", "one of repeat, black, clamp", kAllDialects,
         "lookups outside [0, 1]^2"},
        {"maxanisotropy", "float", "8", "", "", kAllDialects, "EWA filter's largest eccentricity"},
        {"trilinear", "bool", "false", "", "", kAllDialects, "trilinear filtering instead of EWA"},
        {"scale", "float", "1", "", "", kAllDialects, "factor on every texel"},
        {"gamma", "float or bool", "1", "", "", kAllDialects,
         "pbrt-v2: exponent after scale; pbrt-v3's bool: texels sRGB-encoded or linear"},
    }));

// In the order unknown-name errors have always listed them.
const TexturePlugin kTextures[] = {
    {{"texture", "bilerp", kAllDialects,
      "float and spectrum: bilinear blend of four values over (s, t) (lrt draft §11.4)",
      kBilerpParams},
     createBilerp<Float>,
     createBilerp<Spectrum>},
    {{"texture", "checkerboard", kAllDialects,
      "float and spectrum: 2D or solid checkerboard, antialiased (lrt draft §11.6.2-11.6.3)",
      kCheckerboardParams},
     createCheckerboard<Float>,
     createCheckerboard<Spectrum>},
    {{"texture", "constant", kAllDialects, "float and spectrum: one value (lrt draft §11.1)",
      kConstantParams},
     createConstant<Float>,
     createConstant<Spectrum>},
    {{"texture", "dots", kAllDialects,
      "float and spectrum: randomly placed polka dots (lrt draft §11.7.2)", kDotsParams},
     createDots<Float>,
     createDots<Spectrum>},
    {{"texture", "fbm", kAllDialects,
      "float and spectrum: fractional Brownian motion noise (lrt draft §11.7.3)", kNoiseParams},
     createFBm<Float>,
     createFBm<Spectrum>},
    {{"texture", "imagemap", kAllDialects,
      "float and spectrum: MIP-mapped image, colour-managed (lrt draft §11.5)", kImageMapParams},
     createImageMap<Float>,
     createImageMap<Spectrum>},
    {{"texture", "marble", kAllDialects,
      "spectrum only: marble from noise-perturbed strata (lrt draft §11.7.5)", kMarbleParams},
     nullptr,
     createMarble},
    {{"texture", "mix", kAllDialects,
      "float and spectrum: tex1 and tex2 blended by amount (lrt draft §11.1.3)", kMixParams},
     createMix<Float>,
     createMix<Spectrum>},
    {{"texture", "scale", kAllDialects, "float and spectrum: tex1 times tex2 (lrt draft §11.1)",
      kScaleParams},
     createScale<Float>,
     createScale<Spectrum>},
    {{"texture", "uv", kAllDialects,
      "spectrum only: the (s, t) coordinates as red and green (lrt draft §11.6.1)", kUVParams},
     nullptr,
     createUV},
    {{"texture",
      "windy",
      kAllDialects,
      "float and spectrum: waves on wind-swept water (lrt draft §11.7.6)",
      {}},
     createWindy<Float>,
     createWindy<Spectrum>},
    {{"texture", "wrinkled", kAllDialects,
      "float and spectrum: turbulence, the absolute noise summed (lrt draft §11.7.4)",
      kNoiseParams},
     createWrinkled<Float>,
     createWrinkled<Spectrum>},
};

}  // namespace

std::span<const TexturePlugin> texturePlugins() { return kTextures; }

}  // namespace candela
