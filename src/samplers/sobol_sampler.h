// pbrt-v3's "sobol" sampler (pbrt 3e §7.7), per pixel: sample i of a pixel is point i of the
// Sobol' sequence (sobol_matrices.h), the image plane its dimensions 0 and 1 and the sampler's
// other dimensions 2, 3, ... in the order they are asked for, each dimension Owen-scrambled
// (owen_scramble.h) by a seed drawn from (pixel, dimension, seed). With 2^k samples per pixel
// the image-plane points are a (0,k,2)-net and every aligned block of 2^j samples is a
// (t,j,s)-net in all dimensions together, as the unscrambled sequence's is. pbrt-v3 spreads one
// unscrambled Sobol' sequence over the whole image and finds each pixel's samples by inverting the
// first two generator matrices; that needs the image's extent in the sampler, which samplers here
// do not have (they also serve pixels outside the image, for light tracing and pre-passes), so each
// pixel gets its own scrambled sequence. Past kSobolDimensions the values are independent uniform
// ones from a hash of (pixel, sample, dimension, seed).
#pragma once

#include "samplers/sampler.h"

namespace candela {

class SobolSampler final : public Sampler {
 public:
  SobolSampler(int samplesPerPixel, uint64_t seed);
  int samplesPerPixel() const override { return samplesPerPixel_; }
  std::unique_ptr<Sampler> clone() const override;
  void startPixelSample(const Point2i& pixel, int sampleIndex) override;
  Float get1D() override;
  Point2f get2D() override;
  Point2f getPixel2D() override;

 private:
  // Sobol' dimension `dimension` of the current sample, scrambled for the pixel.
  Float dimensionValue(uint64_t dimension) const;

  int samplesPerPixel_;
  uint64_t seed_;
  Point2i pixel_;
  uint32_t sampleIndex_ = 0;
  uint64_t dimension_ = 2;  // the next dimension after the image plane's two
};

}  // namespace candela
