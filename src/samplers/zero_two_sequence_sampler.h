// pbrt-v3's "02sequence" sampler (pbrt 3e §7.5; pbrt-v2's "lowdiscrepancy" with pbrt-v3's
// dimension budget): the first `dimensions` 1D dimensions of a pixel's samples are van der
// Corput values and the first `dimensions` 2D dimensions, the image plane being 2D dimension 0,
// are (0,2)-sequence points (zero_two_sequence.h), each dimension scrambled per pixel by a random
// XOR and its samples reordered by a nested permutation of the sample index, as the
// lowdiscrepancy sampler does (lowdiscrepancy_sampler.h). With 2^k samples per pixel each such
// dimension's points are a (0,k,1)- or (0,k,2)-net. 1D and 2D dimensions are counted
// separately, as pbrt-v3's pixel samplers count their 1D and 2D arrays; past `dimensions` the
// values are independent uniform ones, as pbrt-v3 draws them from its random generator.
#pragma once

#include "samplers/sampler.h"

namespace candela {

class ZeroTwoSequenceSampler : public Sampler {
 public:
  // samplesPerPixel must be a power of two (the factory rounds up); dimensions >= 1.
  ZeroTwoSequenceSampler(int samplesPerPixel, int dimensions, uint64_t seed);
  int samplesPerPixel() const override { return samplesPerPixel_; }
  int dimensions() const { return dimensions_; }
  std::unique_ptr<Sampler> clone() const override;
  void startPixelSample(const Point2i& pixel, int sampleIndex) override;
  Float get1D() override;
  Point2f get2D() override;
  Point2f getPixel2D() override;

 protected:
  int log2Samples() const { return log2Samples_; }
  uint64_t seed() const { return seed_; }
  const Point2i& pixel() const { return pixel_; }
  uint32_t sampleIndex() const { return sampleIndex_; }

 private:
  Float value1D(uint64_t dimension) const;
  Point2f value2D(uint64_t dimension) const;

  int samplesPerPixel_;
  int log2Samples_;
  int dimensions_;
  uint64_t seed_;
  Point2i pixel_;
  uint32_t sampleIndex_ = 0;
  uint64_t dimension1D_ = 0;
  uint64_t dimension2D_ = 1;  // 2D dimension 0 is the image plane's
};

}  // namespace candela
