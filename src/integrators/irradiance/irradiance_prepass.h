// The irradiance cache's prepass: fills the cache before the render so that the render only
// reads it (pbrt 2e §15.5 primes its cache with a one-sample-per-pixel pass, since a cache
// filled on demand makes neighbouring pixels disagree). Here the pass is deterministic: camera
// rays through pixel centres on grids from coarse to fine over the whole image (whatever the crop
// window), every pixel by the last grid. Each grid is one round, taken in batches of a fixed
// number of grid points: the batch's rays find the points the cache cannot yet answer, in
// parallel against the cache as the batch began; the points are numbered in pixel order, a point
// that earlier points of the batch will surely cover is dropped, the rest are estimated in
// parallel, each from a seed given by its round and number, and inserted in number order. The
// cache is a function of (scene, camera, resolution, sampler seed) only.
#pragma once

#include <functional>
#include <vector>

#include "integrators/irradiance/irradiance_estimate.h"
#include "integrators/irradiance/irradiance_octree.h"

namespace candela {

// How the prepass runs: threads (0: all cores), whether to show progress, and what every thread
// that traces rays must call first (the render's floating-point mode; empty: none).
struct PrepassOptions {
  int nThreads = 0;
  bool quiet = true;
  std::function<void()> setUpThread;
};

struct PrepassPlan {
  Point2i resolution;  // the film's full resolution
  int firstStep = 8;   // pixels between the first grid's points; halved each round down to 1
  Float minWeight = 0.5f, cosMaxAngle = 1;
  Float minPixelSpacing = 0;  // the smallest radius a sample gets, in pixels
};

// The points that the camera ray shades and that the cache cannot answer; called concurrently
// while the cache does not change.
using FindUncachedPoints =
    std::function<void(const RayDifferential& cameraRay, IntegratorContext& ctx,
                       std::vector<IrradianceQuery>* uncached)>;
// A new cache sample for the query, from the seed only.
using ComputeCacheSample =
    std::function<IrradianceSample(const IrradianceQuery& query, uint64_t seed, RayStats& stats)>;

struct PrepassResult {
  RayStats rays;
  uint64_t cameraRays = 0;  // one per grid point
  uint64_t uncached = 0;    // points the cache could not answer when their round began
  uint64_t estimated = 0;   // samples computed and inserted
};

PrepassResult fillIrradianceCache(IrradianceOctree& cache, const Camera& camera,
                                  const Sampler& sampler, const PrepassPlan& plan,
                                  const FindUncachedPoints& findUncached,
                                  const ComputeCacheSample& compute, const PrepassOptions& options);

}  // namespace candela
