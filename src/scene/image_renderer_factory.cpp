// Integrator / Renderer statements that select a whole-image renderer.
#include "scene/plugin_factories.h"
#include "scene/sppm_factory.h"

namespace candela {

std::unique_ptr<ImageRenderer> createImageRenderer(const PluginDesc& integrator,
                                                   const PluginDesc& renderer,
                                                   const ImageRendererContext& context) {
  if (integrator.name == "sppm") return createSppmRenderer(integrator, context);
  (void)renderer;
  (void)context;
  return nullptr;
}

}  // namespace candela
