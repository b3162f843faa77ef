#include "integrators/adaptive_render.h"

#include <algorithm>

#include "film/error_metrics.h"
#include "integrators/pixel_sample_integrator.h"

namespace candela {

namespace {
constexpr int kDefaultMinSamples = 16;
int roundUpToGroup(int n) { return (n + kCameraRayGroup - 1) / kCameraRayGroup * kCameraRayGroup; }
}  // namespace

std::vector<int> adaptivePassEnds(int samplesPerPixel, const AdaptiveSampling& adaptive) {
  const int spp = std::max(1, samplesPerPixel);
  const int minSamples = adaptive.minSamples > 0 ? adaptive.minSamples : kDefaultMinSamples;
  std::vector<int> ends{std::min(spp, minSamples)};
  const int step = roundUpToGroup(minSamples);
  while (ends.back() < spp) {
    const int done = ends.back();
    ends.push_back(std::min(spp, done + std::max(step, roundUpToGroup(done / 8))));
  }
  return ends;
}

ProgressiveResult renderAdaptive(const RenderPass& renderPass, const Film& film,
                                 int samplesPerPixel, const ProgressiveOptions& options,
                                 const std::vector<int>& leading) {
  const double limit = options.adaptive.noiseThreshold * options.adaptive.noiseThreshold;
  PixelMask mask;
  mask.bounds = film.pixelBounds();
  const Bounds2i& b = mask.bounds;
  const int width = std::max(0, b.pMax.x - b.pMin.x), height = std::max(0, b.pMax.y - b.pMin.y);
  mask.active.assign(size_t(width) * size_t(height), 1);
  // The leading passes, then the adaptive ones from the larger of their end and the minimum.
  AdaptiveSampling adaptive = options.adaptive;
  const int leadEnd = leading.empty() ? 0 : leading.back();
  adaptive.minSamples =
      std::max(adaptive.minSamples > 0 ? adaptive.minSamples : kDefaultMinSamples, leadEnd);
  std::vector<int> ends = leading;
  for (int end : adaptivePassEnds(samplesPerPixel, adaptive))
    if (end > leadEnd) ends.push_back(end);
  const int firstCheck = std::min(std::max(1, samplesPerPixel), adaptive.minSamples);
  size_t passesDone = 0;  // continuingShare runs after each pass of ends, in order
  // A pixel stops for good once its noise is at the threshold at two checks in a row: no later
  // sample changes it. One check is not enough: a pixel whose light comes by rare paths can see
  // none of them in its first samples, and its estimate is then zero (in the indirect room at
  // --quick, 64 of 4,096 pixels stopped black at 16 samples and held a fifth of the image's
  // error at threshold 0.0125).
  std::vector<uint8_t> metOnce(mask.active.size(), 0);
  auto continuingShare = [&] {
    if (ends[passesDone++] < firstCheck) return 1.0;
    size_t active = 0;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const size_t i = size_t(y) * size_t(width) + size_t(x);
        if (mask.active[i]) {
          const bool met = estimatePixelRelMse(film, Point2i(b.pMin.x + x, b.pMin.y + y)) <= limit;
          if (met && metOnce[i]) mask.active[i] = 0;
          metOnce[i] = met;
        }
        active += mask.active[i];
      }
    return mask.active.empty() ? 0.0 : double(active) / double(mask.active.size());
  };
  ProgressiveOptions po = options;
  po.render.pixels = &mask;
  return renderPasses(renderPass, ends, po, continuingShare);
}

}  // namespace candela
