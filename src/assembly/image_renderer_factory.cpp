// Integrator / Renderer statements that select a whole-image renderer, through the tables of
// integrator_plugins.h.
#include "assembly/integrator_plugins.h"
#include "assembly/plugin_factories.h"

namespace candela {

std::unique_ptr<ImageRenderer> createImageRenderer(const PluginDesc& integrator,
                                                   const PluginDesc& renderer,
                                                   const ImageRendererContext& context) {
  // The integrator's choice first: "sppm" or "mlt" wins over any Renderer statement. Unknown
  // names are no error here: createSurfaceIntegrator reports the integrator's, and render_job.cpp
  // warns of the renderer's.
  if (const IntegratorPlugin* i = findPlugin(integratorPlugins(), integrator.name))
    if (i->makeImageRenderer) return i->makeImageRenderer(integrator, context);
  if (const IntegratorPlugin* r = findPlugin(rendererPlugins(), renderer.name))
    if (r->makeImageRenderer) return r->makeImageRenderer(renderer, context);
  return nullptr;
}

}  // namespace candela
