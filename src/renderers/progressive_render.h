// Rendering in passes of doubling sample counts (1, 2, 4, ... spp in total), so that error can be
// measured against run time while the render goes on, and the render can stop on a time budget or
// an error target. Every pass adds the next sample indices to the same film, so the final image is
// bit-identical to a one-pass render of the same samples.
#pragma once

#include <functional>

#include "renderers/sampler_renderer.h"

namespace candela {

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

ProgressiveResult renderProgressive(const SamplerRenderer& renderer, const Scene& scene, Film& film,
                                    int samplesPerPixel, const ProgressiveOptions& options);

}  // namespace candela
