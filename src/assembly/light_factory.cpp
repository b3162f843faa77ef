// LightSource / AreaLightSource "name" -> Light (lrt draft ch. 13): the lights themselves, their
// parameters and their names are the tables of lights/light_plugins.cpp.
#include "assembly/plugin_factories.h"
#include "lights/light_plugins.h"

namespace candela {

std::unique_ptr<Light> createLight(const LightDesc& desc, const ImageLoader& loadImage) {
  const LightPlugin& plugin = requirePlugin(lightPlugins(), "light", desc.name, desc.loc);
  return plugin.create({desc.params, desc.loc, desc.lightToWorld.start, loadImage});
}

std::unique_ptr<AreaLight> createAreaLight(const PluginDesc& desc, const Shape* shape) {
  return requirePlugin(areaLightPlugins(), "area light", desc.name, desc.loc)
      .create(desc.params, desc.loc, shape);
}

}  // namespace candela
