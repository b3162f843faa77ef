#include "samplers/adaptive_sampler.h"

#include <cmath>

namespace candela {

namespace {
// pbrt-v2's threshold: a relative luminance difference above one half calls for more samples.
constexpr Float kMaxContrast = 0.5f;
}  // namespace

AdaptiveSampler::AdaptiveSampler(int minSamples, int maxSamples, AdaptiveMethod method,
                                 uint64_t seed)
    : minSamples_(minSamples), method_(method), seed_(seed), positions_(maxSamples, seed) {}

std::unique_ptr<Sampler> AdaptiveSampler::clone() const {
  return std::make_unique<AdaptiveSampler>(minSamples_, samplesPerPixel(), method_, seed_);
}

void AdaptiveSampler::startPixelSample(const Point2i& pixel, int sampleIndex) {
  positions_.startPixelSample(pixel, sampleIndex);
}

bool AdaptiveSampler::needsMoreSamples(std::span<const PixelSampleResult> initial) const {
  if (initial.size() < 2) return false;
  if (method_ == AdaptiveMethod::ShapeId) {
    for (size_t i = 1; i < initial.size(); ++i)
      if (initial[i].surfaceId != initial[0].surfaceId) return true;
    return false;
  }
  double mean = 0;
  for (const PixelSampleResult& r : initial) mean += double(r.L.y());
  mean /= double(initial.size());
  // A black pixel has no contrast to measure (pbrt-v2 would divide by zero here).
  if (!(mean > 0)) return false;
  for (const PixelSampleResult& r : initial)
    if (std::abs(double(r.L.y()) - mean) > kMaxContrast * mean) return true;
  return false;
}

}  // namespace candela
