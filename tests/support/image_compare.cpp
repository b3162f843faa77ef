#include "support/image_compare.h"

#include <cmath>
#include <stdexcept>

namespace candela::test {

RoundingComparison compareUpToRounding(const ImageBuffer& a, const ImageBuffer& b, float relative,
                                       float absolute) {
  if (a.data.size() != b.data.size() || a.channelCount() != b.channelCount())
    throw std::invalid_argument("compareUpToRounding: the images differ in size");
  RoundingComparison r;
  int nc = a.channelCount();
  r.pixels = a.pixelCount();
  r.values = a.data.size();
  for (size_t px = 0; px < r.pixels; ++px) {
    bool ok = true;
    for (int c = 0; c < nc; ++c) {
      float x = a.data[px * nc + c], y = b.data[px * nc + c];
      ok = ok && std::abs(x - y) <= relative * 0.5f * (std::abs(x) + std::abs(y)) + absolute;
      r.identicalValues += x == y;
      r.sumA += x;
      r.sumB += y;
    }
    r.flipped += !ok;
  }
  return r;
}

}  // namespace candela::test
