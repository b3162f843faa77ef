// Material "name" -> Material (lrt draft ch. 10; pbrt-v2's parameter names and defaults).
#include "materials/matte.h"
#include "scene/plugin_factories.h"

namespace candela {

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

}  // namespace candela
