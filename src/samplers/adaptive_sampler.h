// The adaptive sampler (pbrt-v2 "adaptive"; lrt draft §7.8 exercise, Kirk & Arvo's caveat that
// such sampling is biased applies): a pixel first takes minSamples samples; when they disagree it
// takes maxSamples in all. "contrast": some sample's luminance differs from their mean by more than
// half the mean. "shapeid": the camera rays did not all hit the same surface (missing everything
// counts as one surface).
// Positions are the low-discrepancy sampler's with maxSamples per pixel: the first minSamples and
// all maxSamples of a pixel are each (0,2)-nets, so the samples taken first are kept, not thrown
// away as pbrt-v2 does.
#pragma once

#include "samplers/lowdiscrepancy_sampler.h"

namespace candela {

enum class AdaptiveMethod { Contrast, ShapeId };

class AdaptiveSampler final : public Sampler {
 public:
  // Both counts powers of two, minSamples <= maxSamples (the factory rounds and checks).
  AdaptiveSampler(int minSamples, int maxSamples, AdaptiveMethod method, uint64_t seed);
  int samplesPerPixel() const override { return positions_.samplesPerPixel(); }
  int initialSamplesPerPixel() const override { return minSamples_; }
  bool needsMoreSamples(std::span<const PixelSampleResult> initial) const override;
  AdaptiveMethod method() const { return method_; }

  std::unique_ptr<Sampler> clone() const override;
  void startPixelSample(const Point2i& pixel, int sampleIndex) override;
  Float get1D() override { return positions_.get1D(); }
  Point2f get2D() override { return positions_.get2D(); }
  Point2f getPixel2D() override { return positions_.getPixel2D(); }

 private:
  int minSamples_;
  AdaptiveMethod method_;
  uint64_t seed_;
  LowDiscrepancySampler positions_;
};

}  // namespace candela
