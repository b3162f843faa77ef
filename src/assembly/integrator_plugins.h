// The integrator and renderer tables: every name the SurfaceIntegrator (pbrt-v2, lrt), Integrator
// (pbrt-v3) and Renderer (pbrt-v2) statements accept, with what each reads. createSurfaceIntegrator
// and createImageRenderer dispatch through them, and their unknown-name errors list them.
#pragma once

#include <memory>
#include <span>

#include "assembly/plugin_factories.h"
#include "core/plugin_spec.h"

namespace candela {

// The surface integrator the sampler renderer runs (arguments as createSurfaceIntegrator's).
using SurfaceIntegratorCreator = std::unique_ptr<SurfaceIntegrator> (*)(const PluginDesc& desc,
                                                                        const Camera* camera,
                                                                        const Bounds2i& pixelBounds,
                                                                        SceneDialect dialect);
// A renderer of the whole image, in place of the sampler renderer and a surface integrator.
using ImageRendererCreator =
    std::unique_ptr<ImageRenderer> (*)(const PluginDesc& desc, const ImageRendererContext& context);

struct IntegratorPlugin {
  PluginSpec spec;
  // An integrator sets exactly one. A renderer sets makeImageRenderer, or neither ("sampler":
  // the sampler renderer, running the scene's surface integrator).
  SurfaceIntegratorCreator makeSurfaceIntegrator = nullptr;
  ImageRendererCreator makeImageRenderer = nullptr;
};

// Kind "integrator": the names of SurfaceIntegrator and Integrator, "sppm" and "mlt" included.
std::span<const IntegratorPlugin> integratorPlugins();
// Kind "renderer": the names of Renderer that candela implements. Any other renders with the
// sampler renderer, after a warning (render_job.cpp).
std::span<const IntegratorPlugin> rendererPlugins();

// The surface integrators' create functions (integrator_factory.cpp), which the table points to.
std::unique_ptr<SurfaceIntegrator> createAmbientOcclusionIntegrator(const PluginDesc& desc,
                                                                    const Camera* camera,
                                                                    const Bounds2i& pixelBounds,
                                                                    SceneDialect dialect);
std::unique_ptr<SurfaceIntegrator> createAoIntegrator(const PluginDesc& desc, const Camera* camera,
                                                      const Bounds2i& pixelBounds,
                                                      SceneDialect dialect);
std::unique_ptr<SurfaceIntegrator> createBdptIntegrator(const PluginDesc& desc,
                                                        const Camera* camera,
                                                        const Bounds2i& pixelBounds,
                                                        SceneDialect dialect);
std::unique_ptr<SurfaceIntegrator> createBidirectionalIntegrator(const PluginDesc& desc,
                                                                 const Camera* camera,
                                                                 const Bounds2i& pixelBounds,
                                                                 SceneDialect dialect);
std::unique_ptr<SurfaceIntegrator> createDipoleSubsurfaceIntegrator(const PluginDesc& desc,
                                                                    const Camera* camera,
                                                                    const Bounds2i& pixelBounds,
                                                                    SceneDialect dialect);
std::unique_ptr<SurfaceIntegrator> createDirectLightingIntegrator(const PluginDesc& desc,
                                                                  const Camera* camera,
                                                                  const Bounds2i& pixelBounds,
                                                                  SceneDialect dialect);
std::unique_ptr<SurfaceIntegrator> createIgiIntegrator(const PluginDesc& desc, const Camera* camera,
                                                       const Bounds2i& pixelBounds,
                                                       SceneDialect dialect);
std::unique_ptr<SurfaceIntegrator> createIrradianceCacheIntegrator(const PluginDesc& desc,
                                                                   const Camera* camera,
                                                                   const Bounds2i& pixelBounds,
                                                                   SceneDialect dialect);
std::unique_ptr<SurfaceIntegrator> createPathIntegrator(const PluginDesc& desc,
                                                        const Camera* camera,
                                                        const Bounds2i& pixelBounds,
                                                        SceneDialect dialect);
std::unique_ptr<SurfaceIntegrator> createPhotonMapIntegrator(const PluginDesc& desc,
                                                             const Camera* camera,
                                                             const Bounds2i& pixelBounds,
                                                             SceneDialect dialect);
std::unique_ptr<SurfaceIntegrator> createVolPathIntegrator(const PluginDesc& desc,
                                                           const Camera* camera,
                                                           const Bounds2i& pixelBounds,
                                                           SceneDialect dialect);
std::unique_ptr<SurfaceIntegrator> createWhittedIntegrator(const PluginDesc& desc,
                                                           const Camera* camera,
                                                           const Bounds2i& pixelBounds,
                                                           SceneDialect dialect);

}  // namespace candela
