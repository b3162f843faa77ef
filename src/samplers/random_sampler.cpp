#include "samplers/random_sampler.h"

#include "samplers/sample_seed.h"

namespace candela {

namespace {

// 64 random bits for one dimension of a sample: the sample's key advanced along a Weyl sequence
// by the golden ratio, then through the 64-bit finaliser (the SplitMix64 construction, Steele et
// al. 2014).
uint64_t dimensionBits(uint64_t sampleKey, uint64_t dimension) {
  return mixBits(sampleKey + (dimension + 1) * 0x9e3779b97f4a7c15ULL);
}

// 24 bits as a float in [0, 1): exact, and never 1.
Float unitFloat(uint64_t bits24) { return Float(bits24) * 0x1p-24f; }

// The top 24 bits and the next 24 as two values in [0, 1).
Point2f pairOf(uint64_t bits) {
  return Point2f(unitFloat(bits >> 40), unitFloat((bits >> 16) & 0xffffff));
}

}  // namespace

RandomSampler::RandomSampler(int samplesPerPixel, uint64_t seed)
    : samplesPerPixel_(samplesPerPixel), seed_(seed) {}

std::unique_ptr<Sampler> RandomSampler::clone() const {
  return std::make_unique<RandomSampler>(samplesPerPixel_, seed_);
}

void RandomSampler::startPixelSample(const Point2i& pixel, int sampleIndex) {
  sampleKey_ = sampleSeed(pixel, uint64_t(sampleIndex), kPixelDimension, seed_);
  dimension_ = 0;
}

Float RandomSampler::get1D() { return unitFloat(dimensionBits(sampleKey_, dimension_++) >> 40); }

Point2f RandomSampler::get2D() { return pairOf(dimensionBits(sampleKey_, dimension_++)); }

Point2f RandomSampler::getPixel2D() { return pairOf(dimensionBits(sampleKey_, kPixelDimension)); }

}  // namespace candela
