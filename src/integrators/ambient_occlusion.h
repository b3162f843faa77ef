// "ambientocclusion" (pbrt-v2's AmbientOcclusionIntegrator): at the first surface a camera ray
// hits, the fraction of directions over the hemisphere on the viewer's side whose rays travel
// maxdist without hitting anything. Grey, in [0, 1]; rays that escape give 0. By default the
// directions are cosine-weighted: the visibility-weighted irradiance fraction, the usual
// definition (pbrt-v3's integrator estimates the same integral unnormalised, in [0, pi]). With
// cosSample false ("bool cossample" false) they are uniform over the hemisphere: pbrt-v2's value.
// The two agree on open and closed surroundings only.
// pbrt-v3's "ao" (Estimate::UnoccludedCosine) estimates the unnormalised integral of cos(theta)
// over the unoccluded directions, in [0, pi], and there cossample changes only the sampling, not
// the value (pbrt-v3 has no maxdist: its probes are unbounded).
#pragma once

#include "integrators/pixel_sample_integrator.h"

namespace candela {

class AmbientOcclusionIntegrator : public PixelSampleIntegrator {
 public:
  enum class Estimate { ClearFraction, UnoccludedCosine };
  AmbientOcclusionIntegrator(int nSamples, Float maxDist, bool cosSample,
                             Estimate estimate = Estimate::ClearFraction)
      : nSamples_(nSamples), maxDist_(maxDist), cosSample_(cosSample), estimate_(estimate) {}
  Spectrum Li(const RayDifferential& ray, const Scene& scene, IntegratorContext& ctx,
              Float* alpha) const override;

 private:
  int nSamples_;
  Float maxDist_;
  bool cosSample_;
  Estimate estimate_;
};

}  // namespace candela
