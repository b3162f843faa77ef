#include "integrators/progressive_render.h"

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
  }
  return "";
}

ProgressiveResult renderProgressive(const RenderPass& renderPass, int samplesPerPixel,
                                    const ProgressiveOptions& options) {
  auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  ProgressiveResult result;
  int done = 0;
  for (int pass = 0; done < samplesPerPixel; ++pass) {
    int next = std::min(samplesPerPixel, std::max(1, 2 * done));
    if (options.timeBudget > 0 && pass > 0) {
      // The next pass takes about (next - done) / done of the time so far.
      double predicted = elapsed() * double(next - done) / double(done);
      if (elapsed() + predicted > options.timeBudget) {
        result.reason = StopReason::TimeBudget;
        break;
      }
    }
    RenderOptions ro = options.render;
    ro.firstSample = done;
    ro.endSample = next;
    ro.quiet = true;
    RenderResult r = renderPass(ro);
    result.total.add(r);
    done = next;
    result.spp = done;
    result.passes = pass + 1;
    result.total.seconds = elapsed();
    if (!options.render.quiet)
      std::fprintf(stderr, "Pass %d: %d spp after %.2fs\n", pass + 1, done, result.total.seconds);
    if (options.afterPass) {
      PassReport report{pass, done, result.total.seconds, result.total};
      if (!options.afterPass(report)) {
        if (done < samplesPerPixel) result.reason = StopReason::TargetError;
        break;
      }
    }
  }
  result.total.seconds = elapsed();
  return result;
}

}  // namespace candela
