#include "samplers/random_sampler.h"

#include "samplers/sample_seed.h"

namespace candela {

RandomSampler::RandomSampler(int samplesPerPixel, uint64_t seed)
    : samplesPerPixel_(samplesPerPixel), seed_(seed) {}

std::unique_ptr<Sampler> RandomSampler::clone() const {
  return std::make_unique<RandomSampler>(samplesPerPixel_, seed_);
}

void RandomSampler::startPixelSample(const Point2i& pixel, int sampleIndex) {
  pixel_ = pixel;
  sampleIndex_ = sampleIndex;
  dimension_ = 0;
}

Float RandomSampler::get1D() {
  RNG rng = sampleRNG(pixel_, uint64_t(sampleIndex_), dimension_++, seed_);
  return rng.uniformFloat();
}

Point2f RandomSampler::get2D() {
  RNG rng = sampleRNG(pixel_, uint64_t(sampleIndex_), dimension_++, seed_);
  Float x = rng.uniformFloat();
  return Point2f(x, rng.uniformFloat());
}

Point2f RandomSampler::getPixel2D() {
  RNG rng = sampleRNG(pixel_, uint64_t(sampleIndex_), kPixelDimension, seed_);
  Float x = rng.uniformFloat();
  return Point2f(x, rng.uniformFloat());
}

}  // namespace candela
