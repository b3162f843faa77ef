#include "samplers/halton_sampler.h"

#include <algorithm>

#include "samplers/sample_seed.h"

namespace candela {

namespace {

// Indices past this count are computed without tables (a slower path; no render takes so many
// samples in a pixel at once).
constexpr int kMaxTabulatedSamples = 4096;

// The digit permutations are the pixel's, the same for all its samples (index 0 in the key).
uint64_t pixelKey(const Point2i& pixel, uint64_t seed) {
  return sampleSeed(pixel, 0, kPixelDimension, seed);
}

uint64_t keyOf(uint64_t pixelKey, uint64_t coordinate) {
  return mixBits(pixelKey + (coordinate + 1) * 0xd1b54a32d192ed03ULL);
}

}  // namespace

HaltonSampler::HaltonSampler(int samplesPerPixel, uint64_t seed)
    : HaltonSampler(samplesPerPixel, seed, nullptr) {}

HaltonSampler::HaltonSampler(int samplesPerPixel, uint64_t seed,
                             std::shared_ptr<const std::vector<Coordinate>> prototype)
    : samplesPerPixel_(samplesPerPixel), seed_(seed), prototype_(std::move(prototype)) {
  if (!prototype_) {
    auto coordinates = std::make_shared<std::vector<Coordinate>>();
    uint32_t count = uint32_t(std::clamp(samplesPerPixel, 1, kMaxTabulatedSamples));
    uint32_t offset = 0;
    for (uint32_t base : kPrimes) {
      coordinates->push_back(Coordinate{FastScrambledRadicalInverse(base, count), 0, offset});
      offset += coordinates->back().inverse.tableSize();
    }
    prototype_ = std::move(coordinates);
  }
  coordinates_ = *prototype_;
  const Coordinate& last = coordinates_.back();
  tables_.resize(last.tableOffset + last.inverse.tableSize());
}

std::unique_ptr<Sampler> HaltonSampler::clone() const {
  return std::unique_ptr<Sampler>(new HaltonSampler(samplesPerPixel_, seed_, prototype_));
}

uint64_t HaltonSampler::coordinateKey(const Point2i& pixel, uint64_t coordinate, uint64_t seed) {
  return keyOf(pixelKey(pixel, seed), coordinate);
}

void HaltonSampler::startPixelSample(const Point2i& pixel, int sampleIndex) {
  if (pixelStamp_ == 0 || pixel != pixel_) {
    ++pixelStamp_;
    pixelKey_ = pixelKey(pixel, seed_);
  }
  pixel_ = pixel;
  sampleIndex_ = uint32_t(sampleIndex);
  coordinate_ = 2;
}

void HaltonSampler::setKey(Coordinate& c, uint64_t coordinate) {
  c.inverse.setKey(keyOf(pixelKey_, coordinate), &tables_[c.tableOffset]);
  c.pixelStamp = pixelStamp_;
}

Float HaltonSampler::randomValue(uint64_t coordinate) const {
  return sampleRNG(pixel_, sampleIndex_, coordinate, seed_).uniformFloat();
}

}  // namespace candela
