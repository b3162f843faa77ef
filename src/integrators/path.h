// "path": unidirectional path tracing with next-event estimation, MIS by the power heuristic and
// Russian roulette (pbrt 2e §15.3). maxdepth bounds the number of scattering events, so a path
// of maxdepth d carries emission seen directly plus up to d reflections. Each vertex traces one
// shadow ray and one ray onward: the BSDF's sample that continues the path is also the BSDF
// strategy of the light's MIS (pbrt 4e §13.4), where pbrt 2e traces a third ray for it.
//
// Russian roulette starts at rrStartDepth. By default (pbrt-v2's scenes) every path faces it there,
// continuing with the throughput's largest channel. With pbrt-v3's rule (its "rrthreshold", on
// for pbrt-v3 scenes) only a path whose throughput is below rrthreshold faces it. Both take the
// throughput times the radiance scaling of the refractions it passed (eta^2 for each entry, pbrt
// 3e §16.1), which pbrt-v2 itself does not undo: only the noise differs from pbrt-v2's. The light a
// vertex samples is chosen by lightsamplestrategy (light_sampler.h); uniform by default, pbrt-v3's
// "spatial" for pbrt-v3 scenes (the light tree past kSpatialMostLights lights).
//
// With guiding (guided_integrator.h), at a vertex whose BSDF has no specular lobe, half of the
// directions are drawn from the field's distribution there and half from the BSDF; the
// mixture's density weighs the light strategy as well, since the direction that continues the
// path is also next-event estimation's scattering sample.
#pragma once

#include <memory>

#include "integrators/guided_integrator.h"
#include "lights/light_sampler.h"

namespace candela {

struct PathSettings {
  int maxDepth = 5;
  int rrStartDepth = 3;
  bool pbrtV3Roulette = false;
  Float rrThreshold = 1;  // with pbrtV3Roulette
  LightSampleStrategy lightStrategy = LightSampleStrategy::Uniform;
  bool guiding = false;
};

class PathIntegrator : public GuidedIntegrator, private FirstHitRadiance {
 public:
  VolumeRegionLight volumeRegionLight() const override { return VolumeRegionLight::EveryRay; }
  explicit PathIntegrator(int maxDepth, int rrStartDepth = 3)
      : PathIntegrator(PathSettings{maxDepth, rrStartDepth}) {}
  explicit PathIntegrator(const PathSettings& settings)
      : GuidedIntegrator(settings.guiding),
        maxDepth_(settings.maxDepth),
        rrStartDepth_(settings.rrStartDepth),
        settings_(settings) {}
  int maxDepth() const { return maxDepth_; }
  const PathSettings& settings() const { return settings_; }
  // Makes the light sampler of a strategy other than uniform (uniform's choice is made inline:
  // no virtual call per vertex that the scene does not need).
  void preprocess(const Scene& scene, const PreprocessOptions& options) override;
  Spectrum Li(const RayDifferential& ray, const Scene& scene, IntegratorContext& ctx,
              Float* alpha) const override;
  // Camera rays traced in groups, each path from its ray's hit (LiFromFirstHit).
  RenderResult renderSamples(const RenderInputs& in, Film& film,
                             const RenderOptions& options) override;
  Spectrum LiFromFirstHit(const RayDifferential& ray, SurfaceInteraction* hit, Float tHit,
                          const Scene& scene, IntegratorContext& ctx, Float* alpha) const override;
  // The radiance arriving along ray without the emission of what it meets first (a surface's Le
  // or, when it escapes, the lights' Le): light that has scattered at least once, as an
  // irradiance estimate's rays need it (pbrt 2e §15.5.3). *hitDistance is the ray parameter of
  // the first hit, infinity when the ray escapes.
  Spectrum scatteredLi(const RayDifferential& ray, const Scene& scene, IntegratorContext& ctx,
                       Float* hitDistance) const;

 private:
  // The first hit when the caller found it: isect, null when the ray escapes, at distance t.
  struct FirstHit {
    SurfaceInteraction* isect;
    Float t;
  };
  Spectrum radiance(const RayDifferential& ray, const Scene& scene, IntegratorContext& ctx,
                    bool firstEmission, Float* alpha, Float* hitDistance,
                    const FirstHit* first = nullptr) const;
  // Guided passes trace camera rays in groups too.
  SampleLoop guidedSampleLoop(const RenderInputs& in, const Film& film) const override;
  int maxDepth_;
  int rrStartDepth_;
  PathSettings settings_;
  std::unique_ptr<LightSampler> lightSampler_;  // null: uniform
};

}  // namespace candela
