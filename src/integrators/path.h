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
// With guiding (Müller, Gross & Novák 2017), the first passes of doubling sample counts, up to a
// quarter of the samples per pixel, train a GuidingField on the incident radiance their paths
// find; at a vertex whose BSDF has no specular lobe, half of the directions are then drawn from
// the field's distribution there and half from the BSDF, weighed by the mixture's density (one-
// sample MIS, §5.1). Every sample, training ones included, goes into the image: each is unbiased.
// Training passes take the full image and every sample index below the training's end whatever
// the crop window or sample range, so that the field, and with it every pixel, is the same bits as
// in the full render.
#pragma once

#include <memory>

#include "integrators/pixel_sample_integrator.h"
#include "lights/light_sampler.h"
#include "transport/guiding_field.h"

namespace candela {

struct PathSettings {
  int maxDepth = 5;
  int rrStartDepth = 3;
  bool pbrtV3Roulette = false;
  Float rrThreshold = 1;  // with pbrtV3Roulette
  LightSampleStrategy lightStrategy = LightSampleStrategy::Uniform;
  bool guiding = false;
};

// The samples per pixel that train path guiding's field: the largest power of two at most a
// quarter of samplesPerPixel (0 below 4, where nothing is guided).
int guidingTrainingSamples(int samplesPerPixel);

class PathIntegrator : public PixelSampleIntegrator, private FirstHitRadiance {
 public:
  VolumeRegionLight volumeRegionLight() const override { return VolumeRegionLight::EveryRay; }
  explicit PathIntegrator(int maxDepth, int rrStartDepth = 3)
      : PathIntegrator(PathSettings{maxDepth, rrStartDepth}) {}
  explicit PathIntegrator(const PathSettings& settings)
      : maxDepth_(settings.maxDepth), rrStartDepth_(settings.rrStartDepth), settings_(settings) {}
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
  // With guiding: training passes, then the rest of the samples guided (see above).
  ProgressiveResult render(const RenderInputs& in, Film& film,
                           const ProgressiveOptions& options) override;
  std::string statsReport() const override;
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
  ProgressiveResult renderGuided(const RenderInputs& in, Film& film,
                                 const ProgressiveOptions& options);
  int maxDepth_;
  int rrStartDepth_;
  PathSettings settings_;
  std::unique_ptr<LightSampler> lightSampler_;  // null: uniform
  // Path guiding's field, during a guided render; paths record into it while recording_.
  std::unique_ptr<GuidingField> guide_;
  bool recording_ = false;
};

}  // namespace candela
