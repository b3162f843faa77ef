#include "samplers/best_candidate_sampler.h"

#include <cmath>

#include "samplers/sample_seed.h"

namespace candela {

namespace {

// The draft's table holds 64 x 64 = 4096 points.
constexpr int kTablePoints = 4096;

int tileSide(int samplesPerPixel) {
  return std::max(1, int(std::ceil(std::sqrt(double(kTablePoints) / samplesPerPixel))));
}

int wrap(int v, int n) { return ((v % n) + n) % n; }

Float wrapUnit(Float v) {
  v -= std::floor(v);
  return std::min(v, kOneMinusEpsilon);
}

}  // namespace

BestCandidateSampler::BestCandidateSampler(int samplesPerPixel, uint64_t seed)
    : samplesPerPixel_(samplesPerPixel),
      seed_(seed),
      imagePattern_(std::make_shared<const BestCandidatePattern>(tileSide(samplesPerPixel),
                                                                 samplesPerPixel, seed)),
      unitPattern_(
          std::make_shared<const BestCandidatePattern>(1, samplesPerPixel, mixBits(seed + 1))) {}

std::unique_ptr<Sampler> BestCandidateSampler::clone() const {
  return std::unique_ptr<Sampler>(new BestCandidateSampler(*this));
}

void BestCandidateSampler::startPixelSample(const Point2i& pixel, int sampleIndex) {
  pixel_ = pixel;
  round_ = uint32_t(sampleIndex) / uint32_t(samplesPerPixel_);
  indexInRound_ = uint32_t(sampleIndex) % uint32_t(samplesPerPixel_);
  dimension_ = 0;
}

uint32_t BestCandidateSampler::permutedIndex(uint64_t dimension) const {
  uint64_t key = hashValues(
      {uint64_t(int64_t(pixel_.x)), uint64_t(int64_t(pixel_.y)), dimension, round_, seed_});
  return permutationElement(indexInRound_, uint32_t(samplesPerPixel_), key);
}

Point2f BestCandidateSampler::getPixel2D() {
  int t = imagePattern_->cellsPerSide();
  int cx = pixel_.x, cy = pixel_.y;
  if (round_ > 0) {
    // Another round: the same pixel takes another cell of the tile.
    uint64_t h = hashValues({round_, seed_});
    cx += int(h % uint64_t(t));
    cy += int((h >> 32) % uint64_t(t));
  }
  return imagePattern_->cellPoint(wrap(cx, t), wrap(cy, t), int(indexInRound_));
}

Float BestCandidateSampler::get1D() {
  uint64_t d = dimension_++;
  Float shift = sampleRNG(pixel_, round_, d, seed_).uniformFloat();
  return wrapUnit(Float(permutedIndex(d)) / Float(samplesPerPixel_) + shift);
}

Point2f BestCandidateSampler::get2D() {
  uint64_t d = dimension_++;
  RNG rng = sampleRNG(pixel_, round_, d, seed_);
  Float sx = rng.uniformFloat(), sy = rng.uniformFloat();
  Point2f p = unitPattern_->cellPoint(0, 0, int(permutedIndex(d)));
  return Point2f(wrapUnit(p.x + sx), wrapUnit(p.y + sy));
}

}  // namespace candela
