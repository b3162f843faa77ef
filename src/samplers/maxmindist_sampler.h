// pbrt-v3's "maxmindist" sampler (pbrt 3e §7.6): the image-plane points of a pixel's 2^m samples
// are the max-min-distance (0,m,2)-net (i / 2^m, C_m i) of max_min_dist_matrices.h, moved to the
// centres of their grid cells, in an order chosen per pixel by a nested permutation of the sample
// index; every other dimension is as in
// the 02sequence sampler. As in pbrt-v3 the net itself is not scrambled, since a random digit
// scramble would keep its strata but not its distances: every pixel has the same image-plane
// points. At most 2^16 samples per pixel (the published matrices stop there).
#pragma once

#include "samplers/zero_two_sequence_sampler.h"

namespace candela {

class MaxMinDistSampler final : public ZeroTwoSequenceSampler {
 public:
  // samplesPerPixel: a power of two, at most 2^kMaxMinDistLog2Max; dimensions >= 1.
  MaxMinDistSampler(int samplesPerPixel, int dimensions, uint64_t seed);
  std::unique_ptr<Sampler> clone() const override;
  Point2f getPixel2D() override;
};

}  // namespace candela
