// Independent uniform samples (pbrt 4e §8.3; not in the lrt draft): the baseline every other
// sampler is compared against. Each sample hashes (pixel, sample index, seed) once; a dimension's
// value is then one more mix of that hash and the dimension (random_sampler.cpp), whose 64 bits
// give a 2D value's two 24-bit halves. Still a pure function of (pixel, sample, dimension, seed).
#pragma once

#include "samplers/sampler.h"

namespace candela {

class RandomSampler final : public Sampler {
 public:
  RandomSampler(int samplesPerPixel, uint64_t seed);
  int samplesPerPixel() const override { return samplesPerPixel_; }
  std::unique_ptr<Sampler> clone() const override;
  void startPixelSample(const Point2i& pixel, int sampleIndex) override;
  Float get1D() override;
  Point2f get2D() override;
  Point2f getPixel2D() override;

 private:
  int samplesPerPixel_;
  uint64_t seed_;
  uint64_t sampleKey_ = 0;  // the hash of (pixel, sample index, seed)
  uint64_t dimension_ = 0;
};

}  // namespace candela
