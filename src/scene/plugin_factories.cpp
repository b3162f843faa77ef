#include "scene/plugin_factories.h"

#include "integrators/direct_lighting.h"
#include "integrators/path.h"
#include "lights/diffuse_area_light.h"
#include "lights/point_light.h"
#include "materials/matte.h"

namespace candela {

void throwUnknownPlugin(const FileLoc& loc, const std::string& kind, const std::string& name,
                        const std::vector<std::string>& known) {
  std::string list;
  for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
  throw SceneError(loc, "unknown " + kind + " '" + name + "' (known: " + list + ")");
}

std::unique_ptr<Material> createMaterial(const MaterialDesc& desc, TextureFactory& textures) {
  const ParamSet& p = desc.params;
  if (desc.name == "matte")
    return std::make_unique<MatteMaterial>(textures.spectrum(p, "Kd", Spectrum(0.5f), desc.loc),
                                           textures.scalar(p, "sigma", 0, desc.loc));
  throwUnknownPlugin(desc.loc, "material", desc.name, {"matte"});
}

std::unique_ptr<Material> createDefaultMaterial(TextureFactory& textures) {
  MaterialDesc d;
  d.name = "matte";
  return createMaterial(d, textures);
}

std::unique_ptr<Light> createLight(const LightDesc& desc) {
  const ParamSet& p = desc.params;
  if (desc.name == "point")
    return std::make_unique<PointLight>(
        desc.lightToWorld.start,
        p.getOneSpectrum("I", Spectrum(1)) * p.getOneSpectrum("scale", Spectrum(1)),
        p.getOnePoint3f("from", Point3f(0, 0, 0)));
  throwUnknownPlugin(desc.loc, "light", desc.name, {"point"});
}

std::unique_ptr<AreaLight> createAreaLight(const PluginDesc& desc, const Shape* shape) {
  const ParamSet& p = desc.params;
  if (desc.name == "area" || desc.name == "diffuse") {
    int nSamples = p.getOneInt("nsamples", 1);
    if (nSamples < 1) throw SceneError(p.locationOf("nsamples", desc.loc), "nsamples must be >= 1");
    return std::make_unique<DiffuseAreaLight>(
        shape, p.getOneSpectrum("L", Spectrum(1)) * p.getOneSpectrum("scale", Spectrum(1)),
        nSamples, p.getOneBool("twosided", false));
  }
  throwUnknownPlugin(desc.loc, "area light", desc.name, {"area", "diffuse"});
}

std::unique_ptr<SurfaceIntegrator> createSurfaceIntegrator(const PluginDesc& desc) {
  const ParamSet& p = desc.params;
  int maxDepth = p.getOneInt("maxdepth", 5);
  if (maxDepth < 0) throw SceneError(p.locationOf("maxdepth", desc.loc), "maxdepth must be >= 0");
  if (desc.name == "directlighting") {
    std::string strategy = p.getOneString("strategy", "all");
    DirectLightingIntegrator::Strategy s;
    if (strategy == "all")
      s = DirectLightingIntegrator::Strategy::All;
    else if (strategy == "one")
      s = DirectLightingIntegrator::Strategy::One;
    else
      throw SceneError(p.locationOf("strategy", desc.loc),
                       "unknown strategy '" + strategy + "' (known: all, one)");
    return std::make_unique<DirectLightingIntegrator>(s, maxDepth);
  }
  if (desc.name == "path") return std::make_unique<PathIntegrator>(maxDepth);
  throwUnknownPlugin(desc.loc, "surface integrator", desc.name, {"directlighting", "path"});
}

}  // namespace candela
