// "volpath": unidirectional path tracing through participating media (pbrt 3e §15.2-15.3).
// Free flights by delta tracking against the medium's majorant (closed form in homogeneous
// media), transmittance of shadow rays by ratio tracking across any number of pure interfaces
// (shapes without a material), next-event estimation at surfaces and in media with multiple
// importance sampling of the light and the BSDF or phase function (power heuristic; the
// scattering sample counts whichever light it meets, pbrt 4e §13.4, where pbrt-v3 counts only
// the light chosen for the light sample), and pbrt-v3's Russian roulette on the throughput,
// without the radiance scaling of refractions, below rrthreshold after three bounces.
//
// The current medium is tracked per path: it starts as the camera's (SceneMedia::camera) and
// changes where a path crosses a surface whose Primitive has a MediumInterface. When the scene
// has pbrt-v2 Volume regions (Scene::volume()), that medium fills all space instead and
// interfaces do not change it. Tracking draws from a per-path RNG seeded from the sampler, so
// the image stays a function of (scene, spp, seed).
//
// The light a vertex samples is chosen by lightsamplestrategy (light_sampler.h; pbrt-v3's default,
// "spatial", for scenes that name no strategy), its estimate divided by the choice's probability.
//
// With guiding (guided_integrator.h), a surface vertex whose BSDF has no specular lobe continues
// the path half of the time in a direction drawn from the field's distribution there, weighed by
// the mixture's density; next-event estimation keeps its own BSDF sample, and medium vertices
// their phase function's. The field learns at surface vertices the light arriving along the
// path, medium scattering on the way included.
#pragma once

#include <memory>

#include "integrators/guided_integrator.h"
#include "lights/light_sampler.h"

namespace candela {

class VolPathIntegrator : public GuidedIntegrator {
 public:
  // maxDepth: scattering events (surface or medium) at most; rrThreshold: Russian roulette
  // starts once the throughput's largest channel falls below it (pbrt-v3's defaults 5 and 1).
  VolPathIntegrator(int maxDepth, Float rrThreshold,
                    LightSampleStrategy lightStrategy = LightSampleStrategy::Uniform,
                    bool guiding = false)
      : GuidedIntegrator(guiding),
        maxDepth_(maxDepth),
        rrThreshold_(rrThreshold),
        lightStrategy_(lightStrategy) {}
  // Makes the light sampler of a strategy other than uniform (chosen inline).
  void preprocess(const Scene& scene, const PreprocessOptions& options) override;
  Spectrum Li(const RayDifferential& ray, const Scene& scene, IntegratorContext& ctx,
              Float* alpha) const override;
  VolumeRegionLight volumeRegionLight() const override { return VolumeRegionLight::Integrator; }

 private:
  int maxDepth_;
  Float rrThreshold_;
  bool hittableLights_ = true;  // some light a scattering sample can meet (set by preprocess)
  LightSampleStrategy lightStrategy_;
  std::unique_ptr<LightSampler> lightSampler_;  // null: uniform
};

}  // namespace candela
