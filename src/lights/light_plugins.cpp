// The lights with pbrt-v2's parameter names and defaults (lrt draft ch. 13); every light
// multiplies its I or L by "scale" (pbrt-v2, pbrt-v3).
#include "lights/light_plugins.h"

#include <filesystem>
#include <optional>

#include "lights/diffuse_area_light.h"
#include "lights/distant_light.h"
#include "lights/goniometric_light.h"
#include "lights/infinite_light.h"
#include "lights/point_light.h"
#include "lights/projection_light.h"
#include "lights/spot_light.h"
#include "textures/image_texture.h"

namespace candela {

namespace {

Spectrum readScale(const ParamSet& p) { return p.getOneSpectrum("scale", Spectrum(1)); }

int readSampleCount(const ParamSet& p, const FileLoc& loc) {
  return p.getOneInt("nsamples", 1, ValueRange::atLeast(1), loc);
}

// The "mapname" image, read relative to the scene file that named it; nullopt when none is named.
// Its numbers are taken as they are (scene_linear), 8-bit files included, as pbrt-v2 and v3 read
// light images: pbrt-v3 decodes sRGB 8-bit files only in its image texture (pbrt 3e §10.4), so a
// PNG diagram, slide or environment is not darkened.
std::optional<ImageBuffer> readMap(const LightInputs& in) {
  std::string name = in.params.getOneString("mapname", "");
  if (name.empty()) return std::nullopt;
  FileLoc loc = in.params.locationOf("mapname", in.loc);
  namespace fs = std::filesystem;
  fs::path path(name);
  if (!path.is_absolute() && !loc.file.empty() && loc.file != "-")
    path = fs::path(loc.file).parent_path() / path;
  std::string where = path.lexically_normal().string();
  if (!in.loadImage)
    throw SceneError(loc, "cannot read light map '" + where + "': no image reader was given");
  ImageBuffer image;
  try {
    image = in.loadImage(where, "scene_linear");
  } catch (const std::exception& e) {
    throw SceneError(loc, "cannot read light map '" + where + "': " + e.what());
  }
  if (!image.consistent()) throw SceneError(loc, "light map '" + where + "' is empty");
  return image;
}

std::shared_ptr<const MIPMap<Spectrum>> mipmapOf(const std::optional<ImageBuffer>& image) {
  if (!image) return nullptr;
  // Periodic, as pbrt-v2 and pbrt-v3 build these maps: within half a texel of a projector slide's
  // edge its light blends with the opposite edge's, which pbrt scenes show (light-projection).
  return std::make_shared<MIPMap<Spectrum>>(image->width, image->height,
                                            spectrumTexels(*image, 1, 1), WrapMode::Repeat);
}

// Each create function reads its parameters into locals first, so that the order in which a
// scene's bad values are reported does not depend on the compiler's argument order.

std::unique_ptr<Light> createPointLight(const LightInputs& in) {
  const ParamSet& p = in.params;
  Spectrum scale = readScale(p);
  Spectrum I = p.getOneSpectrum("I", Spectrum(1));
  Point3f from = p.getOnePoint3f("from", Point3f(0, 0, 0));
  return std::make_unique<PointLight>(in.lightToWorld, I * scale, from);
}

std::unique_ptr<Light> createSpotLight(const LightInputs& in) {
  const ParamSet& p = in.params;
  Spectrum scale = readScale(p);
  Spectrum I = p.getOneSpectrum("I", Spectrum(1));
  Point3f from = p.getOnePoint3f("from", Point3f(0, 0, 0));
  Point3f to = p.getOnePoint3f("to", Point3f(0, 0, 1));
  Float coneAngle = p.getOneFloat("coneangle", 30);
  Float coneDelta = p.getOneFloat("conedeltaangle", 5);
  return std::make_unique<SpotLight>(in.lightToWorld, I * scale, from, to, coneAngle, coneDelta);
}

std::unique_ptr<Light> createDistantLight(const LightInputs& in) {
  const ParamSet& p = in.params;
  Spectrum scale = readScale(p);
  Spectrum L = p.getOneSpectrum("L", Spectrum(1));
  Point3f from = p.getOnePoint3f("from", Point3f(0, 0, 0));
  Point3f to = p.getOnePoint3f("to", Point3f(0, 0, 1));
  return std::make_unique<DistantLight>(in.lightToWorld, L * scale, from, to);
}

std::unique_ptr<Light> createProjectionLight(const LightInputs& in) {
  const ParamSet& p = in.params;
  Spectrum scale = readScale(p);
  std::optional<ImageBuffer> image = readMap(in);
  Float aspect = image ? Float(image->width) / Float(image->height) : 1;  // not integer division
  Spectrum I = p.getOneSpectrum("I", Spectrum(1));
  Float fov = p.getOneFloat("fov", 45);
  return std::make_unique<ProjectionLight>(in.lightToWorld, I * scale, fov, mipmapOf(image),
                                           aspect);
}

std::unique_ptr<Light> createGoniometricLight(const LightInputs& in) {
  const ParamSet& p = in.params;
  Spectrum scale = readScale(p);
  Spectrum I = p.getOneSpectrum("I", Spectrum(1));
  std::shared_ptr<const MIPMap<Spectrum>> map = mipmapOf(readMap(in));
  return std::make_unique<GoniometricLight>(in.lightToWorld, I * scale, std::move(map));
}

std::unique_ptr<Light> createInfiniteLight(const LightInputs& in) {
  const ParamSet& p = in.params;
  Spectrum scale = readScale(p);
  int nSamples = readSampleCount(p, in.loc);
  LatLongMap map;
  if (std::optional<ImageBuffer> image = readMap(in))
    map = {image->width, image->height, spectrumTexels(*image, 1, 1)};
  Spectrum L = p.getOneSpectrum("L", Spectrum(1));
  return std::make_unique<InfiniteAreaLight>(in.lightToWorld, L * scale, nSamples, std::move(map));
}

std::unique_ptr<AreaLight> createDiffuseAreaLight(const ParamSet& p, const FileLoc& loc,
                                                  const Shape* shape) {
  int nSamples = readSampleCount(p, loc);
  Spectrum L = p.getOneSpectrum("L", Spectrum(1));
  Spectrum scale = readScale(p);
  bool twoSided = p.getOneBool("twosided", false);
  return std::make_unique<DiffuseAreaLight>(shape, L * scale, nSamples, twoSided);
}

constexpr std::string_view kSpec = "spectrum";
constexpr std::string_view kPoint = "point3";

constexpr ParamSpec kScale{"scale", kSpec, "1", "", "", kAllDialects, "multiplies I or L"};
constexpr ParamSpec kSamples{
    "nsamples", "integer", "1", "", "at least 1", kAllDialects, "light samples per shading point"};
constexpr ParamSpec kMap{
    "mapname", "string", "(none)", "", "", kAllDialects, "image file, relative to the scene"};
constexpr ParamSpec kIntensity{"I", kSpec, "1", "", "", kAllDialects, "radiant intensity"};
constexpr ParamSpec kRadiance{"L", kSpec, "1", "", "", kAllDialects, "emitted radiance"};
constexpr ParamSpec kFrom{"from", kPoint, "0 0 0", "", "", kAllDialects, "position"};

constexpr ParamSpec kPointParams[] = {kScale, kIntensity, kFrom};
constexpr ParamSpec kSpotParams[] = {
    kScale,
    kIntensity,
    kFrom,
    {"to", kPoint, "0 0 1", "", "", kAllDialects, "point the cone is aimed at"},
    {"coneangle", "float", "30", "", "", kAllDialects, "half-angle of the cone, degrees"},
    {"conedeltaangle", "float", "5", "", "", kAllDialects, "width of the edge's falloff, degrees"}};
constexpr ParamSpec kDistantParams[] = {
    kScale,
    kRadiance,
    {"from", kPoint, "0 0 0", "", "", kAllDialects, "with to: the direction light comes from"},
    {"to", kPoint, "0 0 1", "", "", kAllDialects, "with from: the direction light travels"}};
constexpr ParamSpec kProjectionParams[] = {
    kScale,
    kMap,
    kIntensity,
    {"fov", "float", "45", "", "", kAllDialects, "field of view of the projection, degrees"}};
constexpr ParamSpec kGoniometricParams[] = {kScale, kIntensity, kMap};
constexpr ParamSpec kInfiniteParams[] = {kScale, kSamples, kMap, kRadiance};
constexpr ParamSpec kDiffuseParams[] = {
    kSamples,
    kRadiance,
    kScale,
    {"twosided", "bool", "false", "", "", kPbrtV3, "emits from both sides of the shape"}};

constexpr LightPlugin kLights[] = {
    {{"light", "point", kAllDialects, "isotropic point source (lrt draft §13.2; pbrt 3e §12.3)",
      kPointParams},
     createPointLight},
    {{"light", "spot", kAllDialects,
      "point source in a cone with a soft edge (lrt draft §13.2.1; pbrt 3e §12.3.1)", kSpotParams},
     createSpotLight},
    {{"light", "distant", kAllDialects,
      "parallel light from one direction (lrt draft §13.3; pbrt 3e §12.4)", kDistantParams},
     createDistantLight},
    {{"light", "projection", kAllDialects,
      "slide projector: an image cast through a perspective (lrt draft §13.2.2; pbrt 3e §12.3.2)",
      kProjectionParams},
     createProjectionLight},
    {{"light", "goniometric", kAllDialects,
      "point source with a goniometric diagram (lrt draft §13.2.3; pbrt 3e §12.3.3)",
      kGoniometricParams},
     createGoniometricLight},
    {{"light", "infinite", kAllDialects,
      "environment light, optionally a latitude-longitude map (lrt draft §13.5; pbrt 3e §12.6)",
      kInfiniteParams},
     createInfiniteLight},
    // pbrt-v2 registers its environment light under both names.
    {{"light", "exinfinite", kLrt | kPbrtV2, "pbrt-v2's other name for infinite (lrt draft §13.5)",
      kInfiniteParams},
     createInfiniteLight},
};

// pbrt-v2 and pbrt-v3 take both names for the one area light.
constexpr AreaLightPlugin kAreaLights[] = {
    {{"area light", "area", kAllDialects,
      "uniform radiance from a shape's surface (lrt draft §13.4; pbrt 3e §12.5)", kDiffuseParams},
     createDiffuseAreaLight},
    {{"area light", "diffuse", kAllDialects, "the same as area (lrt draft §13.4; pbrt 3e §12.5)",
      kDiffuseParams},
     createDiffuseAreaLight},
};

}  // namespace

std::span<const LightPlugin> lightPlugins() { return kLights; }

std::span<const AreaLightPlugin> areaLightPlugins() { return kAreaLights; }

}  // namespace candela
