#include "samplers/stratified_sampler.h"

#include "samplers/sample_seed.h"

namespace candela {

StratifiedSampler::StratifiedSampler(int xSamples, int ySamples, bool jitter, uint64_t seed)
    : xSamples_(xSamples), ySamples_(ySamples), jitter_(jitter), seed_(seed) {}

std::unique_ptr<Sampler> StratifiedSampler::clone() const {
  return std::make_unique<StratifiedSampler>(xSamples_, ySamples_, jitter_, seed_);
}

void StratifiedSampler::startPixelSample(const Point2i& pixel, int sampleIndex) {
  pixel_ = pixel;
  sampleIndex_ = sampleIndex;
  dimension_ = 0;
}

int StratifiedSampler::stratum(uint64_t dimension, int n) const {
  // Sample indices past n (more samples than strata) start another round of the strata with a
  // fresh permutation, so every block of n consecutive samples is still stratified.
  uint64_t round = uint64_t(sampleIndex_ / n);
  uint32_t i = uint32_t(sampleIndex_ % n);
  uint64_t key = hashValues(
      {uint64_t(int64_t(pixel_.x)), uint64_t(int64_t(pixel_.y)), dimension, round, seed_});
  return int(permutationElement(i, uint32_t(n), key));
}

Float StratifiedSampler::get1D() {
  uint64_t d = dimension_++;
  int n = xSamples_ * ySamples_;
  int s = stratum(d, n);
  Float jitter = 0.5f;
  if (jitter_) jitter = sampleRNG(pixel_, uint64_t(sampleIndex_), d, seed_).uniformFloat();
  return std::min((Float(s) + jitter) / Float(n), kOneMinusEpsilon);
}

Point2f StratifiedSampler::sample2D(uint64_t dimension) const {
  int s = stratum(dimension, xSamples_ * ySamples_);
  int sx = s % xSamples_, sy = s / xSamples_;
  Float jx = 0.5f, jy = 0.5f;
  if (jitter_) {
    RNG rng = sampleRNG(pixel_, uint64_t(sampleIndex_), dimension, seed_);
    jx = rng.uniformFloat();
    jy = rng.uniformFloat();
  }
  return Point2f(std::min((Float(sx) + jx) / Float(xSamples_), kOneMinusEpsilon),
                 std::min((Float(sy) + jy) / Float(ySamples_), kOneMinusEpsilon));
}

Point2f StratifiedSampler::get2D() { return sample2D(dimension_++); }

Point2f StratifiedSampler::getPixel2D() { return sample2D(kPixelDimension); }

}  // namespace candela
