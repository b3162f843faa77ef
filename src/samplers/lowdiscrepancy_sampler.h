// The low-discrepancy sampler (lrt draft §7.5.3; pbrt-v2 LDSampler): every dimension of a
// pixel's samples, the image plane included, is the (0,2)-sequence (zero_two_sequence.h) in 2D or
// van der Corput in 1D, scrambled per pixel and dimension by a random XOR. With 2^k samples per
// pixel, each 2D dimension's points are a (0,k,2)-net and each 1D dimension's put one value in
// every interval [i/2^k, (i+1)/2^k). The draft shuffles each dimension's samples to pair the
// dimensions up at random; here each dimension permutes the sample index with a nested
// permutation, which does the same while keeping every aligned block of 2^j samples a net (the
// adaptive sampler relies on it). The draft's Hammersley image-plane pattern spans the whole
// image, which cannot be computed one pixel at a time; per pixel, the (0,2)-sequence's first 2^k
// points are a (0,k,2)-net as Hammersley's 2^k points are.
#pragma once

#include "samplers/sampler.h"

namespace candela {

class LowDiscrepancySampler final : public Sampler {
 public:
  // samplesPerPixel must be a power of two (the factory rounds up).
  LowDiscrepancySampler(int samplesPerPixel, uint64_t seed);
  int samplesPerPixel() const override { return samplesPerPixel_; }
  std::unique_ptr<Sampler> clone() const override;
  void startPixelSample(const Point2i& pixel, int sampleIndex) override;
  Float get1D() override;
  Point2f get2D() override;
  Point2f getPixel2D() override;

 private:
  // The pixel's scrambling and index-permutation key for a dimension.
  uint64_t dimensionKey(uint64_t dimension) const;
  Point2f sample2D(uint64_t dimension) const;

  int samplesPerPixel_;
  int log2Samples_;
  uint64_t seed_;
  Point2i pixel_;
  uint32_t sampleIndex_ = 0;
  uint64_t dimension_ = 0;
};

}  // namespace candela
