// The best-candidate sampler (lrt draft §7.6; pbrt-v2 "bestcandidate"). The image plane is tiled
// with a best-candidate pattern (best_candidate_pattern.h) of T x T pixels, T chosen so that the
// tile holds about 4096 points (64 x 64 pixels at one sample per pixel, as the draft's table):
// pixel (x, y) takes the points of cell (x mod T, y mod T), so image samples are spread evenly
// within and across pixels. Every other dimension uses a second pattern of samplesPerPixel points
// on the unit torus (2D) or the lattice i/n (1D), shifted by a random toroidal Cranley-Patterson
// offset and with the samples permuted, both chosen per pixel and dimension: the draft's random
// shifts of the table's time and lens values, computable one pixel at a time. Sample indices past
// samplesPerPixel start a new round with another cell and new shifts.
#pragma once

#include "samplers/best_candidate_pattern.h"
#include "samplers/sampler.h"

namespace candela {

class BestCandidateSampler final : public Sampler {
 public:
  BestCandidateSampler(int samplesPerPixel, uint64_t seed);
  int samplesPerPixel() const override { return samplesPerPixel_; }
  // Clones share the patterns, which are never modified.
  std::unique_ptr<Sampler> clone() const override;
  void startPixelSample(const Point2i& pixel, int sampleIndex) override;
  Float get1D() override;
  Point2f get2D() override;
  Point2f getPixel2D() override;

  const BestCandidatePattern& imagePattern() const { return *imagePattern_; }
  const BestCandidatePattern& unitPattern() const { return *unitPattern_; }

 private:
  BestCandidateSampler(const BestCandidateSampler& other) = default;
  // The current sample's position among the pixel's, permuted per dimension.
  uint32_t permutedIndex(uint64_t dimension) const;

  int samplesPerPixel_;
  uint64_t seed_;
  std::shared_ptr<const BestCandidatePattern> imagePattern_, unitPattern_;
  Point2i pixel_;
  uint32_t round_ = 0, indexInRound_ = 0;
  uint64_t dimension_ = 0;
};

}  // namespace candela
