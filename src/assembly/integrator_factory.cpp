// SurfaceIntegrator / Integrator / Renderer statements -> the Integrator, through the tables of
// integrators/integrator_plugins.h.
#include "assembly/plugin_factories.h"
#include "integrators/integrator_plugins.h"

namespace candela {

std::unique_ptr<PixelSampleIntegrator> createSurfaceIntegrator(const PluginDesc& desc,
                                                               const Camera* camera,
                                                               const Bounds2i& pixelBounds,
                                                               SceneDialect dialect) {
  const IntegratorPlugin& plugin =
      requirePlugin(integratorPlugins(), "integrator", desc.name, desc.loc);
  // "sppm" and "mlt": createWholeImageIntegrator makes them, so only a direct call gets here.
  if (!plugin.makePixelSampleIntegrator)
    throw SceneError(desc.loc, "integrator '" + desc.name +
                                   "' renders the whole image; it is not a surface integrator");
  return plugin.makePixelSampleIntegrator({.name = desc.name,
                                           .params = desc.params,
                                           .loc = desc.loc,
                                           .camera = camera,
                                           .pixelBounds = pixelBounds,
                                           .dialect = dialect});
}

std::unique_ptr<Integrator> createWholeImageIntegrator(const PluginDesc& integrator,
                                                       const PluginDesc& renderer,
                                                       const WholeImageContext& context) {
  auto make = [&](const IntegratorPlugin& plugin, const PluginDesc& desc) {
    return plugin.makeWholeImageIntegrator({.name = desc.name,
                                            .params = desc.params,
                                            .loc = desc.loc,
                                            .camera = context.camera,
                                            .sampler = context.sampler,
                                            .pixelBounds = context.pixelBounds,
                                            .seed = context.seed,
                                            .quick = context.quick,
                                            .sppOverride = context.sppOverride});
  };
  // The integrator's choice first: "sppm" or "mlt" wins over any Renderer statement. Unknown
  // names are no error here: createSurfaceIntegrator reports the integrator's, and render_job.cpp
  // warns of the renderer's.
  if (const IntegratorPlugin* i = findPlugin(integratorPlugins(), integrator.name))
    if (i->makeWholeImageIntegrator) return make(*i, integrator);
  if (const IntegratorPlugin* r = findPlugin(rendererPlugins(), renderer.name))
    if (r->makeWholeImageIntegrator) return make(*r, renderer);
  return nullptr;
}

}  // namespace candela
