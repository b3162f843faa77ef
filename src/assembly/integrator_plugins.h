// The integrator and renderer tables: every name the SurfaceIntegrator (pbrt-v2, lrt), Integrator
// (pbrt-v3) and Renderer (pbrt-v2) statements accept, with what each reads. createSurfaceIntegrator
// and createWholeImageIntegrator dispatch through them, and their unknown-name errors list them.
#pragma once

#include <memory>
#include <span>

#include "assembly/plugin_factories.h"
#include "core/plugin_spec.h"

namespace candela {

// An integrator of camera samples, pixel by pixel (arguments as createSurfaceIntegrator's).
using PixelSampleIntegratorCreator =
    std::unique_ptr<PixelSampleIntegrator> (*)(const PluginDesc& desc, const Camera* camera,
                                               const Bounds2i& pixelBounds, SceneDialect dialect);
// An integrator of the whole image at once (SPPM, Metropolis).
using WholeImageIntegratorCreator =
    std::unique_ptr<Integrator> (*)(const PluginDesc& desc, const WholeImageContext& context);

struct IntegratorPlugin {
  PluginSpec spec;
  // An integrator sets exactly one. A renderer sets makeWholeImageIntegrator, or neither
  // ("sampler": the scene's pixel-sample integrator renders).
  PixelSampleIntegratorCreator makePixelSampleIntegrator = nullptr;
  WholeImageIntegratorCreator makeWholeImageIntegrator = nullptr;
};

// Kind "integrator": the names of SurfaceIntegrator and Integrator, "sppm" and "mlt" included.
std::span<const IntegratorPlugin> integratorPlugins();
// Kind "renderer": the names of Renderer that candela implements. Any other renders with the
// scene's pixel-sample integrator, after a warning (render_job.cpp).
std::span<const IntegratorPlugin> rendererPlugins();

// The pixel-sample integrators' create functions (integrator_factory.cpp), which the table points
// to.
std::unique_ptr<PixelSampleIntegrator> createAmbientOcclusionIntegrator(const PluginDesc& desc,
                                                                        const Camera* camera,
                                                                        const Bounds2i& pixelBounds,
                                                                        SceneDialect dialect);
std::unique_ptr<PixelSampleIntegrator> createAoIntegrator(const PluginDesc& desc,
                                                          const Camera* camera,
                                                          const Bounds2i& pixelBounds,
                                                          SceneDialect dialect);
std::unique_ptr<PixelSampleIntegrator> createBdptIntegrator(const PluginDesc& desc,
                                                            const Camera* camera,
                                                            const Bounds2i& pixelBounds,
                                                            SceneDialect dialect);
std::unique_ptr<PixelSampleIntegrator> createBidirectionalIntegrator(const PluginDesc& desc,
                                                                     const Camera* camera,
                                                                     const Bounds2i& pixelBounds,
                                                                     SceneDialect dialect);
std::unique_ptr<PixelSampleIntegrator> createDipoleSubsurfaceIntegrator(const PluginDesc& desc,
                                                                        const Camera* camera,
                                                                        const Bounds2i& pixelBounds,
                                                                        SceneDialect dialect);
std::unique_ptr<PixelSampleIntegrator> createDirectLightingIntegrator(const PluginDesc& desc,
                                                                      const Camera* camera,
                                                                      const Bounds2i& pixelBounds,
                                                                      SceneDialect dialect);
std::unique_ptr<PixelSampleIntegrator> createIgiIntegrator(const PluginDesc& desc,
                                                           const Camera* camera,
                                                           const Bounds2i& pixelBounds,
                                                           SceneDialect dialect);
std::unique_ptr<PixelSampleIntegrator> createIrradianceCacheIntegrator(const PluginDesc& desc,
                                                                       const Camera* camera,
                                                                       const Bounds2i& pixelBounds,
                                                                       SceneDialect dialect);
std::unique_ptr<PixelSampleIntegrator> createPathIntegrator(const PluginDesc& desc,
                                                            const Camera* camera,
                                                            const Bounds2i& pixelBounds,
                                                            SceneDialect dialect);
std::unique_ptr<PixelSampleIntegrator> createPhotonMapIntegrator(const PluginDesc& desc,
                                                                 const Camera* camera,
                                                                 const Bounds2i& pixelBounds,
                                                                 SceneDialect dialect);
std::unique_ptr<PixelSampleIntegrator> createVolPathIntegrator(const PluginDesc& desc,
                                                               const Camera* camera,
                                                               const Bounds2i& pixelBounds,
                                                               SceneDialect dialect);
std::unique_ptr<PixelSampleIntegrator> createWhittedIntegrator(const PluginDesc& desc,
                                                               const Camera* camera,
                                                               const Bounds2i& pixelBounds,
                                                               SceneDialect dialect);

}  // namespace candela
