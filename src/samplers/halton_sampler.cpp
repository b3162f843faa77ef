#include "samplers/halton_sampler.h"

#include "samplers/radical_inverse.h"
#include "samplers/sample_seed.h"

namespace candela {

HaltonSampler::HaltonSampler(int samplesPerPixel, uint64_t seed)
    : samplesPerPixel_(samplesPerPixel), seed_(seed) {}

std::unique_ptr<Sampler> HaltonSampler::clone() const {
  return std::make_unique<HaltonSampler>(samplesPerPixel_, seed_);
}

void HaltonSampler::startPixelSample(const Point2i& pixel, int sampleIndex) {
  pixel_ = pixel;
  sampleIndex_ = uint32_t(sampleIndex);
  coordinate_ = 2;
}

Float HaltonSampler::coordinateValue(uint64_t coordinate) const {
  if (coordinate >= uint64_t(kPrimeTableSize))
    return sampleRNG(pixel_, sampleIndex_, coordinate, seed_).uniformFloat();
  // The digit permutations are the pixel's, the same for all its samples (index 0 in the key).
  uint64_t key = sampleSeed(pixel_, 0, coordinate, seed_);
  return scrambledRadicalInverse(sampleIndex_, kPrimes[coordinate], key);
}

Float HaltonSampler::get1D() { return coordinateValue(coordinate_++); }

Point2f HaltonSampler::get2D() {
  uint64_t c = coordinate_;
  coordinate_ += 2;
  return Point2f(coordinateValue(c), coordinateValue(c + 1));
}

Point2f HaltonSampler::getPixel2D() { return Point2f(coordinateValue(0), coordinateValue(1)); }

}  // namespace candela
