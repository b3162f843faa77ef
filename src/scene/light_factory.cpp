// LightSource / AreaLightSource "name" -> Light (lrt draft ch. 13).
#include "lights/diffuse_area_light.h"
#include "lights/point_light.h"
#include "scene/plugin_factories.h"

namespace candela {

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

}  // namespace candela
