#include "samplers/maxmindist_sampler.h"

#include <cassert>
#include <cmath>

#include "samplers/max_min_dist_matrices.h"
#include "samplers/sample_seed.h"
#include "samplers/zero_two_sequence.h"

namespace candela {

MaxMinDistSampler::MaxMinDistSampler(int samplesPerPixel, int dimensions, uint64_t seed)
    : ZeroTwoSequenceSampler(samplesPerPixel, dimensions, seed) {
  assert(log2Samples() <= kMaxMinDistLog2Max);
}

std::unique_ptr<Sampler> MaxMinDistSampler::clone() const {
  return std::make_unique<MaxMinDistSampler>(samplesPerPixel(), dimensions(), seed());
}

Point2f MaxMinDistSampler::getPixel2D() {
  // Samples past the pixel's count repeat the net, each block of 2^m in its own order.
  const int m = log2Samples();
  uint32_t block = sampleIndex() >> m;
  uint32_t within = sampleIndex() & ((1u << m) - 1);
  uint64_t key = hashValues({sampleSeed(pixel(), 0, kPixelDimension, seed()), block});
  uint32_t i = nestedIndexPermutation(within, m, key);
  // Each point moved by half a cell of the 2^m x 2^m grid it lies on, to the cell's centre:
  // pbrt-v3 keeps the corners, which puts the pixel's samples on average half a cell below and
  // left of its centre. The move keeps every point in its elementary intervals and every distance.
  uint32_t halfCell = 0x80000000u >> m;
  return Point2f(std::ldexp(Float(2 * i + 1), -(m + 1)),
                 bitsToUnitFloat(maxMinDistBits(i, m) | halfCell));
}

}  // namespace candela
