// Integrator / Renderer statements that select a whole-image renderer.
#include "scene/plugin_factories.h"

namespace candela {

std::unique_ptr<ImageRenderer> createImageRenderer(const PluginDesc& integrator,
                                                   const PluginDesc& renderer,
                                                   const ImageRendererContext& context) {
  (void)integrator;
  (void)renderer;
  (void)context;
  return nullptr;
}

}  // namespace candela
