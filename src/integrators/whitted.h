// "whitted": Whitted's ray tracer (pbrt 2e §1.3.6; lrt draft ch. 1). The direct term takes one
// sample of every light, weighted by the full BSDF and the cosine, and needs no MIS because
// only light sampling is used; glossy and diffuse surfaces lit by area lights are therefore
// noisier than with "directlighting", while point-lit scenes are exact.
#pragma once

#include "integrators/specular_recursion.h"

namespace candela {

class WhittedIntegrator : public SpecularRecursionIntegrator {
 public:
  VolumeRegionLight volumeRegionLight() const override { return VolumeRegionLight::EveryRay; }
  explicit WhittedIntegrator(int maxDepth) : SpecularRecursionIntegrator(maxDepth) {}

 protected:
  Spectrum directLight(const SurfaceInteraction& isect, const BSDF& bsdf, const Scene& scene,
                       IntegratorContext& ctx) const override;
};

}  // namespace candela
