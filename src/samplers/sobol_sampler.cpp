#include "samplers/sobol_sampler.h"

#include "samplers/owen_scramble.h"
#include "samplers/sample_seed.h"
#include "samplers/sobol_matrices.h"
#include "samplers/zero_two_sequence.h"

namespace candela {

SobolSampler::SobolSampler(int samplesPerPixel, uint64_t seed)
    : samplesPerPixel_(samplesPerPixel), seed_(seed) {}

std::unique_ptr<Sampler> SobolSampler::clone() const {
  return std::make_unique<SobolSampler>(samplesPerPixel_, seed_);
}

void SobolSampler::startPixelSample(const Point2i& pixel, int sampleIndex) {
  pixel_ = pixel;
  sampleIndex_ = uint32_t(sampleIndex);
  dimension_ = 2;
}

Float SobolSampler::dimensionValue(uint64_t dimension) const {
  if (dimension >= uint64_t(kSobolDimensions))
    return sampleRNG(pixel_, sampleIndex_, dimension, seed_).uniformFloat();
  // The scramble is the pixel's, the same for all its samples (index 0 in the key), so that its
  // samples together stay a scrambled net.
  uint32_t scramble = uint32_t(sampleSeed(pixel_, 0, dimension, seed_));
  return bitsToUnitFloat(owenScrambleBits(sobolBits(sampleIndex_, int(dimension)), scramble));
}

Float SobolSampler::get1D() { return dimensionValue(dimension_++); }

Point2f SobolSampler::get2D() {
  uint64_t d = dimension_;
  dimension_ += 2;
  return Point2f(dimensionValue(d), dimensionValue(d + 1));
}

Point2f SobolSampler::getPixel2D() { return Point2f(dimensionValue(0), dimensionValue(1)); }

}  // namespace candela
