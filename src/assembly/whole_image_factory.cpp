// Integrator / Renderer statements that select a whole-image integrator, through the tables of
// integrator_plugins.h.
#include "assembly/integrator_plugins.h"
#include "assembly/plugin_factories.h"

namespace candela {

std::unique_ptr<Integrator> createWholeImageIntegrator(const PluginDesc& integrator,
                                                       const PluginDesc& renderer,
                                                       const WholeImageContext& context) {
  // The integrator's choice first: "sppm" or "mlt" wins over any Renderer statement. Unknown
  // names are no error here: createSurfaceIntegrator reports the integrator's, and render_job.cpp
  // warns of the renderer's.
  if (const IntegratorPlugin* i = findPlugin(integratorPlugins(), integrator.name))
    if (i->makeWholeImageIntegrator) return i->makeWholeImageIntegrator(integrator, context);
  if (const IntegratorPlugin* r = findPlugin(rendererPlugins(), renderer.name))
    if (r->makeWholeImageIntegrator) return r->makeWholeImageIntegrator(renderer, context);
  return nullptr;
}

}  // namespace candela
