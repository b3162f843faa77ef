// pbrt-v2's volume integrators (lrt draft §16.7) with their parameters.
#include "transport/volume_integrator_plugins.h"

namespace candela {

namespace {

constexpr unsigned kV2 = kLrt | kPbrtV2;

Float readStepSize(const ParamSet& params, const FileLoc& loc) {
  return params.getOneFloat("stepsize", 1, ValueRange::positive(), loc);
}

std::unique_ptr<VolumeIntegrator> createEmissionIntegrator(const ParamSet& params,
                                                           const FileLoc& loc) {
  return std::make_unique<EmissionIntegrator>(readStepSize(params, loc));
}

std::unique_ptr<VolumeIntegrator> createSingleScatteringIntegrator(const ParamSet& params,
                                                                   const FileLoc& loc) {
  return std::make_unique<SingleScatteringIntegrator>(readStepSize(params, loc));
}

constexpr ParamSpec kStepParams[] = {
    {"stepsize", "float", "1", "", "positive and finite", kV2, "ray-marching step, world units"}};

constexpr VolumeIntegratorPlugin kVolumeIntegrators[] = {
    {{"volume integrator", "emission", kV2,
      "absorption and emission only (lrt draft §16.7; pbrt 2e §16.2)", kStepParams},
     createEmissionIntegrator},
    {{"volume integrator", "single", kV2,
      "single scattering from one light per step (lrt draft §16.7; pbrt 2e §16.3)", kStepParams},
     createSingleScatteringIntegrator},
};

}  // namespace

std::span<const VolumeIntegratorPlugin> volumeIntegratorPlugins() { return kVolumeIntegrators; }

}  // namespace candela
