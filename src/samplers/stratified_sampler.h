// Jittered stratified sampling (lrt draft §7.3): each pixel's xs x ys samples fall one per
// stratum in every dimension. A per-dimension pseudo-random permutation of the strata pairs the
// dimensions up at random (the draft shuffles lens and time patterns and uses Latin hypercubes
// for integrator samples; a permutation per dimension gives the same decorrelation with every
// value computable on its own).
#pragma once

#include "samplers/sampler.h"

namespace candela {

class StratifiedSampler final : public Sampler {
 public:
  StratifiedSampler(int xSamples, int ySamples, bool jitter, uint64_t seed);
  int samplesPerPixel() const override { return xSamples_ * ySamples_; }
  int xSamples() const { return xSamples_; }
  int ySamples() const { return ySamples_; }
  bool jitter() const { return jitter_; }
  std::unique_ptr<Sampler> clone() const override;
  void startPixelSample(const Point2i& pixel, int sampleIndex) override;
  // 1D dimensions have xs * ys strata; 2D dimensions (and the pixel) xs x ys.
  Float get1D() override;
  Point2f get2D() override;
  Point2f getPixel2D() override;

 private:
  // The stratum this pixel sample occupies in a dimension with n strata.
  int stratum(uint64_t dimension, int n) const;
  Point2f sample2D(uint64_t dimension) const;

  int xSamples_, ySamples_;
  bool jitter_;
  uint64_t seed_;
  Point2i pixel_;
  int sampleIndex_ = 0;
  uint64_t dimension_ = 0;
};

}  // namespace candela
