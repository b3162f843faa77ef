#include "integrators/progressive_render.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace candela {

const char* stopReasonName(StopReason r) {
  switch (r) {
    case StopReason::Completed:
      return "completed";
    case StopReason::TimeBudget:
      return "time budget";
    case StopReason::TargetError:
      return "target error";
    case StopReason::NoiseThreshold:
      return "noise threshold";
  }
  return "";
}

std::vector<int> doublingPassEnds(int samplesPerPixel) {
  std::vector<int> ends;
  for (int done = 0; done < samplesPerPixel;)
    ends.push_back(done = std::min(samplesPerPixel, std::max(1, 2 * done)));
  return ends;
}

ProgressiveResult renderPasses(const RenderPass& renderPass, const std::vector<int>& ends,
                               const ProgressiveOptions& options,
                               const std::function<double()>& continuingShare) {
  auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  ProgressiveResult result;
  const int samplesPerPixel = ends.empty() ? 0 : ends.back();
  int done = 0;
  double share = 1;  // of the pixels, that the next pass takes
  double work = 0;   // sample indices taken so far, times the share of pixels that took them
  for (size_t pass = 0; pass < ends.size(); ++pass) {
    const int next = ends[pass];
    if (options.timeBudget > 0 && pass > 0) {
      // The next pass takes about its share of the work so far's time.
      double predicted = elapsed() * share * double(next - done) / work;
      if (elapsed() + predicted > options.timeBudget) {
        result.reason = StopReason::TimeBudget;
        break;
      }
    }
    RenderOptions ro = options.render;
    ro.firstSample = done;
    ro.endSample = next;
    ro.quiet = true;
    result.total.add(renderPass(ro));
    work += share * double(next - done);
    done = next;
    result.spp = done;
    result.passes = int(pass) + 1;
    result.total.seconds = elapsed();
    if (continuingShare) share = continuingShare();
    if (!options.render.quiet) {
      std::fprintf(stderr, "Pass %zu: %d spp after %.2fs", pass + 1, done, result.total.seconds);
      if (continuingShare) std::fprintf(stderr, ", %.1f%% of pixels continue", 100 * share);
      std::fprintf(stderr, "\n");
    }
    if (options.afterPass) {
      PassReport report{int(pass), done, result.total.seconds, result.total};
      if (!options.afterPass(report)) {
        if (done < samplesPerPixel) result.reason = StopReason::TargetError;
        break;
      }
    }
    if (share == 0) {
      if (done < samplesPerPixel) result.reason = StopReason::NoiseThreshold;
      break;
    }
  }
  result.total.seconds = elapsed();
  return result;
}

ProgressiveResult renderProgressive(const RenderPass& renderPass, int samplesPerPixel,
                                    const ProgressiveOptions& options) {
  return renderPasses(renderPass, doublingPassEnds(samplesPerPixel), options);
}

}  // namespace candela
