// LightSource / AreaLightSource "name" -> Light (lrt draft ch. 13): the lights themselves, their
// parameters and their names are the tables of assembly/light_plugins.cpp.
#include "assembly/light_plugins.h"
#include "assembly/plugin_factories.h"

namespace candela {

std::unique_ptr<Light> createLight(const LightDesc& desc,
                                   const TextureFactory::ImageLoader& loadImage) {
  return requirePlugin(lightPlugins(), "light", desc.name, desc.loc).create(desc, loadImage);
}

std::unique_ptr<AreaLight> createAreaLight(const PluginDesc& desc, const Shape* shape) {
  return requirePlugin(areaLightPlugins(), "area light", desc.name, desc.loc).create(desc, shape);
}

}  // namespace candela
