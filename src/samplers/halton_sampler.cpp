#include "samplers/halton_sampler.h"

#include <algorithm>

#include "samplers/sample_seed.h"

namespace candela {

namespace {

// Indices past this count are computed without tables (a slower path; no render takes so many
// samples in a pixel at once).
constexpr int kMaxTabulatedSamples = 4096;

// Coordinates keyed at once when a sample asks for one not keyed yet in its pixel.
constexpr uint64_t kKeysAhead = 4;

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
      coordinates->push_back(Coordinate{FastScrambledRadicalInverse(base, count), offset});
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
  if (!started_ || pixel != pixel_) {
    started_ = true;
    pixelKey_ = pixelKey(pixel, seed_);
    keyedEnd_ = 0;
  }
  pixel_ = pixel;
  sampleIndex_ = uint32_t(sampleIndex);
  coordinate_ = 2;
  fastEnd_ = sampleIndex_ < coordinates_[0].inverse.count() ? keyedEnd_ : 0;
}

Float HaltonSampler::slowValue(uint64_t coordinate) {
  if (coordinate >= uint64_t(kPrimeTableSize)) return randomValue(coordinate);
  // Keys a few coordinates ahead: their hash chains are independent and overlap in the
  // processor, where one key at a time waits for each chain (the next ones are nearly always
  // asked for next).
  uint64_t end = std::min<uint64_t>(std::max(coordinate + 1, keyedEnd_ + kKeysAhead),
                                    uint64_t(kPrimeTableSize));
  for (; keyedEnd_ < end; ++keyedEnd_) {
    Coordinate& c = coordinates_[keyedEnd_];
    c.inverse.setKey(keyOf(pixelKey_, keyedEnd_), &tables_[c.tableOffset]);
  }
  const Coordinate& c = coordinates_[coordinate];
  if (sampleIndex_ >= c.inverse.count())
    return c.inverse.value(sampleIndex_, &tables_[c.tableOffset]);
  fastEnd_ = keyedEnd_;
  return c.inverse.tabulatedValue(sampleIndex_, &tables_[c.tableOffset]);
}

Point2f HaltonSampler::slowPair(uint64_t c) {
  Float x = c < fastEnd_ ? tabulatedValue(c) : slowValue(c);
  return Point2f(x, c + 1 < fastEnd_ ? tabulatedValue(c + 1) : slowValue(c + 1));
}

Float HaltonSampler::randomValue(uint64_t coordinate) const {
  return sampleRNG(pixel_, sampleIndex_, coordinate, seed_).uniformFloat();
}

}  // namespace candela
