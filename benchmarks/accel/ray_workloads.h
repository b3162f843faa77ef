// The rays of the accelerator benchmark, made once per scene so that every aggregate traces the
// very same ones: camera rays over the image, diffuse bounce rays (cosine-distributed about the
// normal at the camera rays' hits) and shadow rays (from those hits to the scene's light
// position). And the timing of one aggregate over one set on a given number of threads.
#pragma once

#include <cstdint>
#include <vector>

#include "accel/aggregate.h"
#include "bench_scenes.h"

namespace candela::bench {

struct RaySets {
  std::vector<Ray> camera, bounce, shadow;
};

// About nCamera camera rays on a regular grid of raster positions; hits are found with
// reference (any correct aggregate).
RaySets makeRays(const BenchScene& scene, const Aggregate& reference, long nCamera, uint64_t seed);

struct TraceResult {
  double seconds = 0;
  long hits = 0;
  double raysPerSecond(size_t n) const { return seconds > 0 ? double(n) / seconds : 0; }
};

// Traces every ray (closest hit, or any hit for anyHit) on `threads` threads; the best of
// `repeats` runs. One thread is timed by that thread's CPU clock (unaffected by other load on
// the machine); several threads by the wall clock (which is, so on a busy machine it is low).
TraceResult trace(const Aggregate& aggregate, const std::vector<Ray>& rays, bool anyHit,
                  int threads, int repeats);

}  // namespace candela::bench
