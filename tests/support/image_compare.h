// Test helper: two renders of the same scene that should agree up to floating-point rounding
// (another aggregate, another subdivision producer): how many pixels differ beyond rounding.
#pragma once

#include <cstddef>

#include "core/image_buffer.h"

namespace candela::test {

struct RoundingComparison {
  size_t pixels = 0;
  // Pixels where some channel has |a - b| > relative (|a| + |b|) / 2 + absolute: a ray that grazes
  // an edge or a silhouette and went the other way.
  size_t flipped = 0;
  size_t identicalValues = 0, values = 0;
  double sumA = 0, sumB = 0;  // over all values
};

RoundingComparison compareUpToRounding(const ImageBuffer& a, const ImageBuffer& b, float relative,
                                       float absolute);

}  // namespace candela::test
