// Seeds for the samplers' per-value generators. Hashing (pixel, sample index, dimension, seed)
// makes each value reproducible on its own, whatever was asked for before (DESIGN.md, data flow
// step 3).
#pragma once

#include <cstdint>

#include "core/rng.h"
#include "core/vector.h"

namespace candela {

// The dimension id of the image-plane sample: outside the range of the running dimension
// counter, so getPixel2D gives the same value whenever in a sample it is called.
inline constexpr uint64_t kPixelDimension = ~uint64_t(0);

inline uint64_t sampleSeed(const Point2i& pixel, uint64_t sampleIndex, uint64_t dimension,
                           uint64_t seed) {
  return hashValues(
      {uint64_t(int64_t(pixel.x)), uint64_t(int64_t(pixel.y)), sampleIndex, dimension, seed});
}

// A generator for one (pixel, sample, dimension): the hash picks the PCG stream, and the seed is
// mixed in again as the starting state so that nearby seeds do not share streams.
inline RNG sampleRNG(const Point2i& pixel, uint64_t sampleIndex, uint64_t dimension,
                     uint64_t seed) {
  return RNG(sampleSeed(pixel, sampleIndex, dimension, seed), mixBits(seed));
}

}  // namespace candela
