// The integrator and renderer tables: every name the SurfaceIntegrator (pbrt-v2, lrt), Integrator
// (pbrt-v3) and Renderer (pbrt-v2) statements accept, with what each reads, and the create
// functions they point to (integrator_params.cpp, photon_map_params.cpp, sppm/sppm_params.cpp,
// metropolis/metropolis_params.cpp). The build (assembly/integrator_factory.cpp) dispatches
// through them, and unknown-name errors, `candela --list-plugins` and `candela --describe` read
// them.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include "cameras/camera.h"
#include "core/compatibility.h"
#include "core/paramset.h"
#include "core/plugin_spec.h"
#include "integrators/integrator.h"
#include "integrators/pixel_sample_integrator.h"
#include "samplers/sampler.h"

namespace candela {

// An integrator statement and what the build knows that an integrator may need.
struct IntegratorInputs {
  const std::string& name;
  const ParamSet& params;
  const FileLoc& loc;
  // The scene's camera, for integrators that connect light paths to it (bdpt, mlt, metropolis);
  // such an integrator with a camera that has no importance is a SceneError naming the camera.
  const Camera* camera = nullptr;
  // The scene's sampler: its samples per pixel (after --spp and --quick). Null for pixel-sample
  // integrators, which are handed one to render with.
  const Sampler* sampler = nullptr;
  Bounds2i pixelBounds;  // the film's (crop window applied), for images besides it
  // The scene's, for the defaults of parameters whose pbrt-v3 default differs from pbrt-v2's
  // behaviour.
  SceneDialect dialect = SceneDialect::PbrtV2;
  uint64_t seed = 0;    // --seed, for whole-image integrators' own random numbers
  bool quick = false;   // --quick
  int sppOverride = 0;  // --spp (0: none), for integrators whose sample count is a parameter
};

// Bad values are SceneErrors at the parameter, or at in.loc.
// An integrator of camera samples, pixel by pixel.
using PixelSampleIntegratorCreator =
    std::unique_ptr<PixelSampleIntegrator> (*)(const IntegratorInputs& in);
// An integrator of the whole image at once (SPPM, Metropolis).
using WholeImageIntegratorCreator = std::unique_ptr<Integrator> (*)(const IntegratorInputs& in);

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
// scene's pixel-sample integrator, after a warning (assembly/render_job.cpp).
std::span<const IntegratorPlugin> rendererPlugins();

// The create functions the tables point to.
std::unique_ptr<PixelSampleIntegrator> createAmbientOcclusionIntegrator(const IntegratorInputs& in);
std::unique_ptr<PixelSampleIntegrator> createAoIntegrator(const IntegratorInputs& in);
std::unique_ptr<PixelSampleIntegrator> createBdptIntegrator(const IntegratorInputs& in);
std::unique_ptr<PixelSampleIntegrator> createBidirectionalIntegrator(const IntegratorInputs& in);
std::unique_ptr<PixelSampleIntegrator> createDipoleSubsurfaceIntegrator(const IntegratorInputs& in);
std::unique_ptr<PixelSampleIntegrator> createDirectLightingIntegrator(const IntegratorInputs& in);
std::unique_ptr<PixelSampleIntegrator> createIgiIntegrator(const IntegratorInputs& in);
std::unique_ptr<PixelSampleIntegrator> createIrradianceCacheIntegrator(const IntegratorInputs& in);
std::unique_ptr<PixelSampleIntegrator> createPathIntegrator(const IntegratorInputs& in);
std::unique_ptr<PixelSampleIntegrator> createPhotonMapIntegrator(const IntegratorInputs& in);
std::unique_ptr<PixelSampleIntegrator> createVolPathIntegrator(const IntegratorInputs& in);
std::unique_ptr<PixelSampleIntegrator> createWhittedIntegrator(const IntegratorInputs& in);
// pbrt-v3's Integrator "sppm" and "mlt", pbrt-v2's Renderer "metropolis".
std::unique_ptr<Integrator> createSppmIntegrator(const IntegratorInputs& in);
std::unique_ptr<Integrator> createMltRenderer(const IntegratorInputs& in);
std::unique_ptr<Integrator> createMetropolisIntegrator(const IntegratorInputs& in);

}  // namespace candela
