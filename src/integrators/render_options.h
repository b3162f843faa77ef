// What a render is asked for and what it reports: the sample range of one pass, the passes of a
// progressive render and their stop conditions, and the counts the command prints and records.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>

#include "core/vector.h"
#include "scene/scene.h"

namespace candela {

struct RenderOptions {
  int nThreads = 0;    // 0: all cores
  int tileSize = 16;   // pixels per tile side
  bool quiet = false;  // no progress output
  // The range of sample indices to take in each pixel: [firstSample, endSample), endSample < 0
  // meaning the sampler's samples per pixel. Rendering [0, a) then [a, b) into one film adds
  // every pixel's samples in the same order as rendering [0, b): the same bits.
  int firstSample = 0;
  int endSample = -1;
};

// A camera sample: its pixel and index there (what --cropwindow and --spp reproduce).
struct PixelSampleIndex {
  Point2i pixel;
  int index = 0;
  // Row by row, then by index: the order in which "first" is the same for any thread count.
  bool operator<(const PixelSampleIndex& o) const {
    if (pixel.y != o.pixel.y) return pixel.y < o.pixel.y;
    if (pixel.x != o.pixel.x) return pixel.x < o.pixel.x;
    return index < o.index;
  }
};

struct RenderResult {
  double seconds = 0;
  uint64_t samples = 0;
  RayStats rays;
  uint64_t nonFiniteSamples = 0;  // NaN or infinite radiance, dropped and counted
  // From the start of the last tile to the end of the render: the time in which some thread had
  // no tile left to take (the scheduling's tail).
  double tailSeconds = 0;
  // The first of them (in PixelSampleIndex order), when they came from camera samples.
  std::optional<PixelSampleIndex> firstNonFinite;
  // Adds another render's counts (rays, samples, non-finite samples, tails; the earlier first).
  void add(const RenderResult& other);
};

enum class StopReason { Completed, TimeBudget, TargetError };
const char* stopReasonName(StopReason r);

struct PassReport {
  int pass = 0;        // 0, 1, 2, ...
  int spp = 0;         // samples per pixel so far
  double seconds = 0;  // wall time so far
  RenderResult total;  // summed over the passes so far
};

struct ProgressiveOptions {
  RenderOptions render;   // firstSample/endSample are set per pass
  double timeBudget = 0;  // seconds; 0 = none. A pass is not started when it is predicted to end
                          // past the budget (a doubling pass takes about as long as all before)
  // Called after each pass; returning false stops the render (an error target reached).
  std::function<bool(const PassReport&)> afterPass;
};

struct ProgressiveResult {
  RenderResult total;
  int spp = 0;
  int passes = 0;
  StopReason reason = StopReason::Completed;
};

}  // namespace candela
