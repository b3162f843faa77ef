// "irradiancecache": Ward's irradiance caching (pbrt 2e §15.5; lrt draft §16.5). Emission and
// direct light from all lights as "directlighting" does, perfect specular reflection and
// transmission by recursion up to maxspeculardepth, and the light that reaches diffuse and glossy
// components after scattering elsewhere from cached irradiance: L = E * rho_hd(wo) / pi, exact for
// Lambertian surfaces and the draft's approximation for glossy ones (pbrt 2e's f(wo, w_avg) E
// agrees on Lambertian ones).
//
// prepare() fills the cache in a deterministic prepass (irradiance_prepass.h); the render only
// reads it, never writes: storing during the render would make the image depend on which pixels
// were rendered first. The prepass has covered every pixel centre, so the points the render
// shades are nearly all answered. Those that are not (seen only by off-centre, lens or time
// samples) take the weighted average of the samples that reach them even when their weight is
// below minweight: those samples were placed for the neighbouring pixel centres, and their
// average is smoother than a fresh estimate. A point that no sample reaches gets a fresh estimate,
// not stored, seeded from its pixel sample.
#pragma once

#include <atomic>
#include <memory>

#include "integrators/irradiance/irradiance_cache_settings.h"
#include "integrators/irradiance/irradiance_estimate.h"
#include "integrators/irradiance/irradiance_octree.h"
#include "integrators/irradiance/irradiance_prepass.h"
#include "integrators/specular_recursion.h"

namespace candela {

class IrradianceCacheIntegrator : public SpecularRecursionIntegrator {
 public:
  explicit IrradianceCacheIntegrator(const IrradianceCacheSettings& settings);
  ~IrradianceCacheIntegrator() override;
  // --quick: a sixteenth of the hemisphere samples of every estimate (pbrt-v2's rule).
  void preprocess(const Scene& scene, const PreprocessOptions& options) override;
  // The first render fills the cache (prepare), then every render reads it, its camera rays
  // with differentials whatever the textures (the cache spaces its samples by their footprint).
  RenderResult renderSamples(const RenderInputs& in, Film& film,
                             const RenderOptions& options) override;
  std::string statsReport() const override;
  const IrradianceCacheSettings& settings() const { return settings_; }
  // The cache prepare() built; null before it, and when maxerror is 0.
  const IrradianceOctree* cache() const { return cache_.get(); }
  // Points the render found no acceptable samples for, and so estimated afresh.
  uint64_t renderMisses() const { return renderMisses_.load(); }

 protected:
  Spectrum directLight(const SurfaceInteraction& isect, const BSDF& bsdf, const Scene& scene,
                       IntegratorContext& ctx) const override;

 private:
  // Fills the cache once, before the first pixel of the first render; what it builds is a
  // function of (scene, camera, film resolution, sampler seed) only, never of threads, crop
  // window or order of completion. Returns the rays it traced.
  RayStats prepare(const Scene& scene, const Camera& camera, const Sampler& sampler,
                   const Film& film, const PrepassOptions& options);
  // The query of one hemisphere at isect: the geometric normal turned to wo's side (reflection)
  // or away from it (transmission), as pbrt 2e orients it.
  IrradianceQuery query(const SurfaceInteraction& isect, bool transmission) const;
  IrradianceSample newSample(const IrradianceQuery& q, const Scene& scene, uint64_t seed,
                             RayStats& stats) const;
  Spectrum indirectLight(const SurfaceInteraction& isect, const BSDF& bsdf, bool transmission,
                         const Scene& scene, IntegratorContext& ctx) const;

  IrradianceCacheSettings settings_;
  bool quickApplied_ = false;
  Float cosMaxAngle_;
  PathIntegrator paths_;
  std::unique_ptr<IrradianceOctree> cache_;
  bool prepared_ = false;
  Float sceneSize_ = kInfinity;
  uint64_t prepassEstimates_ = 0, prepassUncached_ = 0;
  double prepassSeconds_ = 0;
  mutable std::atomic<uint64_t> renderMisses_{0}, renderWeakLookups_{0};
};

}  // namespace candela
