// "ambientocclusion" (pbrt-v2's AmbientOcclusionIntegrator): at the first surface a camera ray
// hits, the fraction of directions over the hemisphere on the viewer's side whose rays travel
// maxdist without hitting anything. Grey, in [0, 1]; rays that escape give 0. The directions are
// cosine-weighted by default (pbrt-v3's "cossample" true: the visibility-weighted irradiance
// fraction, the usual definition); with cosSample false they are uniform over the hemisphere,
// which is what pbrt-v2 computes. The two agree on open and closed surroundings only.
#pragma once

#include "integrators/integrator.h"

namespace candela {

class AmbientOcclusionIntegrator : public SurfaceIntegrator {
 public:
  AmbientOcclusionIntegrator(int nSamples, Float maxDist, bool cosSample)
      : nSamples_(nSamples), maxDist_(maxDist), cosSample_(cosSample) {}
  Spectrum Li(const RayDifferential& ray, const Scene& scene, IntegratorContext& ctx,
              Float* alpha) const override;

 private:
  int nSamples_;
  Float maxDist_;
  bool cosSample_;
};

}  // namespace candela
