// LightSource / AreaLightSource "name" -> Light (lrt draft ch. 13), with pbrt-v2's parameter
// names and defaults; every light multiplies its I or L by "scale" (pbrt-v2).
#include <filesystem>

#include "assembly/plugin_factories.h"
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

int readSampleCount(const ParamSet& p, const FileLoc& loc) {
  return p.getOneInt("nsamples", 1, ValueRange::atLeast(1), loc);
}

// The "mapname" image, read relative to the scene file that named it; nullopt when none is named.
// Its numbers are taken as they are (scene_linear), 8-bit files included, as pbrt-v2 and v3 read
// light images: pbrt-v3 decodes sRGB 8-bit files only in its image texture (pbrt 3e §10.4), so a
// PNG diagram, slide or environment is not darkened.
std::optional<ImageBuffer> readMap(const LightDesc& desc, const TextureFactory::ImageLoader& load) {
  std::string name = desc.params.getOneString("mapname", "");
  if (name.empty()) return std::nullopt;
  FileLoc loc = desc.params.locationOf("mapname", desc.loc);
  namespace fs = std::filesystem;
  fs::path path(name);
  if (!path.is_absolute() && !loc.file.empty() && loc.file != "-")
    path = fs::path(loc.file).parent_path() / path;
  std::string where = path.lexically_normal().string();
  if (!load)
    throw SceneError(loc, "cannot read light map '" + where + "': no image reader was given");
  ImageBuffer image;
  try {
    image = load(where, "scene_linear");
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

}  // namespace

std::unique_ptr<Light> createLight(const LightDesc& desc,
                                   const TextureFactory::ImageLoader& loadImage) {
  const ParamSet& p = desc.params;
  const Transform& toWorld = desc.lightToWorld.start;
  Spectrum scale = p.getOneSpectrum("scale", Spectrum(1));
  if (desc.name == "point")
    return std::make_unique<PointLight>(toWorld, p.getOneSpectrum("I", Spectrum(1)) * scale,
                                        p.getOnePoint3f("from", Point3f(0, 0, 0)));
  if (desc.name == "spot")
    return std::make_unique<SpotLight>(
        toWorld, p.getOneSpectrum("I", Spectrum(1)) * scale,
        p.getOnePoint3f("from", Point3f(0, 0, 0)), p.getOnePoint3f("to", Point3f(0, 0, 1)),
        p.getOneFloat("coneangle", 30), p.getOneFloat("conedeltaangle", 5));
  if (desc.name == "distant")
    return std::make_unique<DistantLight>(toWorld, p.getOneSpectrum("L", Spectrum(1)) * scale,
                                          p.getOnePoint3f("from", Point3f(0, 0, 0)),
                                          p.getOnePoint3f("to", Point3f(0, 0, 1)));
  if (desc.name == "projection") {
    std::optional<ImageBuffer> image = readMap(desc, loadImage);
    Float aspect = image ? Float(image->width) / Float(image->height) : 1;  // not integer division
    return std::make_unique<ProjectionLight>(toWorld, p.getOneSpectrum("I", Spectrum(1)) * scale,
                                             p.getOneFloat("fov", 45), mipmapOf(image), aspect);
  }
  if (desc.name == "goniometric")
    return std::make_unique<GoniometricLight>(toWorld, p.getOneSpectrum("I", Spectrum(1)) * scale,
                                              mipmapOf(readMap(desc, loadImage)));
  // pbrt-v2 registers its environment light under both names.
  if (desc.name == "infinite" || desc.name == "exinfinite") {
    int nSamples = readSampleCount(p, desc.loc);
    LatLongMap map;
    if (std::optional<ImageBuffer> image = readMap(desc, loadImage))
      map = {image->width, image->height, spectrumTexels(*image, 1, 1)};
    return std::make_unique<InfiniteAreaLight>(toWorld, p.getOneSpectrum("L", Spectrum(1)) * scale,
                                               nSamples, std::move(map));
  }
  throwUnknownPlugin(
      desc.loc, "light", desc.name,
      {"distant", "exinfinite", "goniometric", "infinite", "point", "projection", "spot"});
}

std::unique_ptr<AreaLight> createAreaLight(const PluginDesc& desc, const Shape* shape) {
  const ParamSet& p = desc.params;
  if (desc.name == "area" || desc.name == "diffuse") {
    int nSamples = readSampleCount(p, desc.loc);
    return std::make_unique<DiffuseAreaLight>(
        shape, p.getOneSpectrum("L", Spectrum(1)) * p.getOneSpectrum("scale", Spectrum(1)),
        nSamples, p.getOneBool("twosided", false));
  }
  throwUnknownPlugin(desc.loc, "area light", desc.name, {"area", "diffuse"});
}

}  // namespace candela
