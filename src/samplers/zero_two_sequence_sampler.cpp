#include "samplers/zero_two_sequence_sampler.h"

#include <cassert>

#include "samplers/sample_seed.h"
#include "samplers/zero_two_sequence.h"

namespace candela {

namespace {

// Seed-key dimension ids: 1D dimension j is 2j, 2D dimension j is 2j + 1; the unstratified
// values past the budget take ids with the top bit set, apart from both.
uint64_t id1D(uint64_t j) { return 2 * j; }
uint64_t id2D(uint64_t j) { return 2 * j + 1; }
constexpr uint64_t kUnstratified = uint64_t(1) << 63;

}  // namespace

ZeroTwoSequenceSampler::ZeroTwoSequenceSampler(int samplesPerPixel, int dimensions, uint64_t seed)
    : samplesPerPixel_(samplesPerPixel),
      log2Samples_(__builtin_ctz(uint32_t(samplesPerPixel))),
      dimensions_(dimensions),
      seed_(seed) {
  assert(samplesPerPixel > 0 && (samplesPerPixel & (samplesPerPixel - 1)) == 0);
  assert(dimensions >= 1);
}

std::unique_ptr<Sampler> ZeroTwoSequenceSampler::clone() const {
  return std::make_unique<ZeroTwoSequenceSampler>(samplesPerPixel_, dimensions_, seed_);
}

void ZeroTwoSequenceSampler::startPixelSample(const Point2i& pixel, int sampleIndex) {
  pixel_ = pixel;
  sampleIndex_ = uint32_t(sampleIndex);
  dimension1D_ = 0;
  dimension2D_ = 1;
}

Float ZeroTwoSequenceSampler::value1D(uint64_t dimension) const {
  if (dimension >= uint64_t(dimensions_))
    return sampleRNG(pixel_, sampleIndex_, kUnstratified | id1D(dimension), seed_).uniformFloat();
  // One scramble and one index permutation per pixel and dimension (index 0 in the key).
  uint64_t key = sampleSeed(pixel_, 0, id1D(dimension), seed_);
  uint32_t n = nestedIndexPermutation(sampleIndex_, log2Samples_, key);
  return bitsToUnitFloat(vanDerCorputBits(n, uint32_t(mixBits(key + 1))));
}

Point2f ZeroTwoSequenceSampler::value2D(uint64_t dimension) const {
  if (dimension >= uint64_t(dimensions_)) {
    RNG rng = sampleRNG(pixel_, sampleIndex_, kUnstratified | id2D(dimension), seed_);
    Float x = rng.uniformFloat();
    return Point2f(x, rng.uniformFloat());
  }
  uint64_t key = sampleSeed(pixel_, 0, id2D(dimension), seed_);
  uint32_t n = nestedIndexPermutation(sampleIndex_, log2Samples_, key);
  uint64_t scramble = mixBits(key + 1);
  return Point2f(bitsToUnitFloat(vanDerCorputBits(n, uint32_t(scramble))),
                 bitsToUnitFloat(sobol2Bits(n, uint32_t(scramble >> 32))));
}

Float ZeroTwoSequenceSampler::get1D() { return value1D(dimension1D_++); }

Point2f ZeroTwoSequenceSampler::get2D() { return value2D(dimension2D_++); }

Point2f ZeroTwoSequenceSampler::getPixel2D() { return value2D(0); }

}  // namespace candela
