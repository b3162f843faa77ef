// What a render is asked for and what it reports: the sample range of one pass, the passes of a
// progressive render and their stop conditions, and the counts the command prints and records.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "core/vector.h"
#include "scene/scene.h"

namespace candela {

// The pixels a pass takes samples in: adaptive sampling's pixels that have not yet converged.
struct PixelMask {
  Bounds2i bounds;
  std::vector<uint8_t> active;  // row by row over bounds; nonzero: take samples
  bool contains(const Point2i& p) const {
    return bounds.inside(p) &&
           active[size_t(p.y - bounds.pMin.y) * size_t(bounds.pMax.x - bounds.pMin.x) +
                  size_t(p.x - bounds.pMin.x)] != 0;
  }
};

struct RenderOptions {
  int nThreads = 0;    // 0: all cores
  int tileSize = 16;   // pixels per tile side
  bool quiet = false;  // no progress output
  // The range of sample indices to take in each pixel: [firstSample, endSample), endSample < 0
  // meaning the sampler's samples per pixel. Rendering [0, a) then [a, b) into one film adds
  // every pixel's samples in the same order as rendering [0, b): the same bits.
  int firstSample = 0;
  int endSample = -1;
  // Non-null: only these pixels take the pass's samples (the rest keep what they have).
  const PixelMask* pixels = nullptr;
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

enum class StopReason { Completed, TimeBudget, TargetError, NoiseThreshold };
const char* stopReasonName(StopReason r);

struct PassReport {
  int pass = 0;        // 0, 1, 2, ...
  int spp = 0;         // samples per pixel so far
  double seconds = 0;  // wall time so far
  RenderResult total;  // summed over the passes so far
};

// Noise-driven adaptive sampling (as Cycles' adaptive_threshold and adaptive_min_samples): every
// pixel takes minSamples, then passes of more samples go only to the pixels whose estimated
// relative error, sqrt of the mean over R, G, B of var / (value^2 + kRelMseEpsilon) from the
// pixel's own samples, is still above noiseThreshold. A pixel's decisions read only its own
// samples, so the image stays a function of (scene, spp, seed) for any thread count, tile size,
// crop window or farm tile. Noise threshold t aims at an image relMSE of about t^2.
struct AdaptiveSampling {
  double noiseThreshold = 0;  // 0: off
  int minSamples = 0;         // 0: the default, 16 (at most the samples per pixel)
  bool enabled() const { return noiseThreshold > 0; }
};

struct ProgressiveOptions {
  RenderOptions render;  // firstSample/endSample are set per pass
  AdaptiveSampling adaptive;
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
