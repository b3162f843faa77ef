// "ambientocclusion" (pbrt-v2's AmbientOcclusionIntegrator): at the first surface a camera ray
// hits, the fraction of cosine-weighted directions over the hemisphere on the viewer's side
// whose rays travel maxdist without hitting anything. Grey, in [0, 1]; rays that escape give 0.
// pbrt-v2's code draws its directions uniformly over the hemisphere instead; the cosine weighting
// is the usual definition of the quantity (the visibility-weighted irradiance fraction), so the
// two agree on open and closed surroundings but not in between.
#pragma once

#include "integrators/integrator.h"

namespace candela {

class AmbientOcclusionIntegrator : public SurfaceIntegrator {
 public:
  AmbientOcclusionIntegrator(int nSamples, Float maxDist)
      : nSamples_(nSamples), maxDist_(maxDist) {}
  Spectrum Li(const RayDifferential& ray, const Scene& scene, IntegratorContext& ctx,
              Float* alpha) const override;

 private:
  int nSamples_;
  Float maxDist_;
};

}  // namespace candela
