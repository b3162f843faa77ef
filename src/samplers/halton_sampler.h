// The Halton sampler (lrt draft §7.5.2; pbrt-v2 "halton"): coordinate c of sample i of a pixel is
// the radical inverse Phi_b(i) in the c-th prime base b, its digits scrambled by random
// permutations chosen per pixel and coordinate (radical_inverse.h). The image plane takes bases 2
// and 3; the other dimensions take 5, 7, 11, ... in the order they are asked for, a 2D dimension
// two of them. pbrt-v2 spreads one Halton sequence over the whole image, which cannot be
// computed one pixel at a time; per pixel, scrambling decorrelates neighbouring pixels and the
// high bases' leading digits. Past the 1024th prime the values are independent uniform ones.
#pragma once

#include "samplers/sampler.h"

namespace candela {

class HaltonSampler final : public Sampler {
 public:
  HaltonSampler(int samplesPerPixel, uint64_t seed);
  int samplesPerPixel() const override { return samplesPerPixel_; }
  std::unique_ptr<Sampler> clone() const override;
  void startPixelSample(const Point2i& pixel, int sampleIndex) override;
  Float get1D() override;
  Point2f get2D() override;
  Point2f getPixel2D() override;

 private:
  // The value of coordinate `coordinate` (0 and 1: the image plane) for the current sample.
  Float coordinateValue(uint64_t coordinate) const;

  int samplesPerPixel_;
  uint64_t seed_;
  Point2i pixel_;
  uint32_t sampleIndex_ = 0;
  uint64_t coordinate_ = 2;  // the next coordinate after the image plane's two
};

}  // namespace candela
