// "directlighting": emitted plus directly reflected light, with Whitted-style recursion through
// specular reflection and transmission up to maxdepth (lrt draft §16.1; pbrt 2e §15.1). The
// direct term uses MIS of a light and a BSDF sample, for all lights or one chosen at random.
#pragma once

#include "integrators/specular_recursion.h"

namespace candela {

class DirectLightingIntegrator : public SpecularRecursionIntegrator {
 public:
  VolumeRegionLight volumeRegionLight() const override { return VolumeRegionLight::EveryRay; }
  enum class Strategy { All, One };
  DirectLightingIntegrator(Strategy strategy, int maxDepth)
      : SpecularRecursionIntegrator(maxDepth), strategy_(strategy) {}

 protected:
  Spectrum directLight(const SurfaceInteraction& isect, const BSDF& bsdf, const Scene& scene,
                       IntegratorContext& ctx) const override;

 private:
  Strategy strategy_;
};

}  // namespace candela
