// A new irradiance estimate (pbrt 2e §15.5.3; lrt draft §16.5): nSamples cosine-distributed rays
// over the hemisphere, each carrying the radiance a path tracer finds along it without the
// emission of what it hits first (that light is the direct term), so E = (pi / N) sum L_i. The
// directions are a scrambled (0,2)-sequence; the scramble and the paths' random numbers come
// from the seed alone, so an estimate is a function of (point, seed).
#pragma once

#include <cstdint>

#include "integrators/irradiance/irradiance_cache_settings.h"
#include "integrators/path.h"

namespace candela {

// A point that needs irradiance: where the rays start, the hemisphere's axis (unit), and the
// world-space size of a pixel there (0 when the camera gave no differentials).
struct IrradianceQuery {
  Interaction at;
  Normal3f n;
  Float pixelSpacing = 0;
};

struct IrradianceEstimate {
  Spectrum E;
  Float harmonicMeanDistance = kInfinity;  // N / sum(1 / d_i), Ward's measure of the surroundings
  Float minHitDistance = kInfinity;
};

// The nFilter brightest radiance values (by luminance) are left out and the rest averaged: the
// lrt draft's guard against rare long paths that make blotches (draft §16.5).
IrradianceEstimate estimateIrradiance(const IrradianceQuery& query, const Scene& scene,
                                      const PathIntegrator& paths, int nSamples, int nFilter,
                                      uint64_t seed, RayStats& stats);

// The radius within which the estimate may be reused: maxError times Ward's harmonic mean
// distance, at most half the nearest hit (pbrt 2e), then clamped to [minPixelSpacing,
// maxPixelSpacing] pixels where the pixel size is known, and never beyond sceneSize.
Float validityRadius(const IrradianceEstimate& estimate, Float pixelSpacing,
                     const IrradianceCacheSettings& settings, Float sceneSize);

}  // namespace candela
