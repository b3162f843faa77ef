#include "samplers/lowdiscrepancy_sampler.h"

#include <cassert>

#include "samplers/sample_seed.h"
#include "samplers/zero_two_sequence.h"

namespace candela {

LowDiscrepancySampler::LowDiscrepancySampler(int samplesPerPixel, uint64_t seed)
    : samplesPerPixel_(samplesPerPixel),
      log2Samples_(__builtin_ctz(uint32_t(samplesPerPixel))),
      seed_(seed) {
  assert(samplesPerPixel > 0 && (samplesPerPixel & (samplesPerPixel - 1)) == 0);
}

std::unique_ptr<Sampler> LowDiscrepancySampler::clone() const {
  return std::make_unique<LowDiscrepancySampler>(samplesPerPixel_, seed_);
}

void LowDiscrepancySampler::startPixelSample(const Point2i& pixel, int sampleIndex) {
  pixel_ = pixel;
  sampleIndex_ = uint32_t(sampleIndex);
  dimension_ = 0;
}

uint64_t LowDiscrepancySampler::dimensionKey(uint64_t dimension) const {
  // The same for every sample of the pixel: one scramble per pixel and dimension (draft §7.5.3).
  return sampleSeed(pixel_, 0, dimension, seed_);
}

Float LowDiscrepancySampler::get1D() {
  uint64_t key = dimensionKey(dimension_++);
  uint32_t n = nestedIndexPermutation(sampleIndex_, log2Samples_, key);
  return bitsToUnitFloat(vanDerCorputBits(n, uint32_t(mixBits(key + 1))));
}

Point2f LowDiscrepancySampler::sample2D(uint64_t dimension) const {
  uint64_t key = dimensionKey(dimension);
  uint32_t n = nestedIndexPermutation(sampleIndex_, log2Samples_, key);
  uint64_t scramble = mixBits(key + 1);
  return Point2f(bitsToUnitFloat(vanDerCorputBits(n, uint32_t(scramble))),
                 bitsToUnitFloat(sobol2Bits(n, uint32_t(scramble >> 32))));
}

Point2f LowDiscrepancySampler::get2D() { return sample2D(dimension_++); }

Point2f LowDiscrepancySampler::getPixel2D() { return sample2D(kPixelDimension); }

}  // namespace candela
