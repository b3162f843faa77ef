// Integrator / Renderer statements that select a whole-image renderer.
#include "assembly/metropolis_params.h"
#include "assembly/plugin_factories.h"
#include "assembly/sppm_factory.h"

namespace candela {

std::unique_ptr<ImageRenderer> createImageRenderer(const PluginDesc& integrator,
                                                   const PluginDesc& renderer,
                                                   const ImageRendererContext& context) {
  if (integrator.name == "sppm") return createSppmRenderer(integrator, context);
  if (integrator.name == "mlt") return createMltRenderer(integrator, context);
  if (renderer.name == "metropolis") return createMetropolisRenderer(renderer, context);
  return nullptr;
}

}  // namespace candela
