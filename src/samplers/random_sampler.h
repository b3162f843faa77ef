// Independent uniform samples (pbrt 4e §8.3; not in the lrt draft): the baseline every other
// sampler is compared against.
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
  Point2i pixel_;
  int sampleIndex_ = 0;
  uint64_t dimension_ = 0;
};

}  // namespace candela
