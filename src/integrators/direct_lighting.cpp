#include "integrators/direct_lighting.h"

#include "transport/light_sampling.h"

namespace candela {

Spectrum DirectLightingIntegrator::directLight(const SurfaceInteraction& isect, const BSDF& bsdf,
                                               const Scene& scene, IntegratorContext& ctx) const {
  if (strategy_ == Strategy::All) return uniformSampleAllLights(isect, bsdf, scene, ctx);
  return uniformSampleOneLight(isect, bsdf, scene, ctx);
}

}  // namespace candela
