// Spectrum::isBlack tests the channels' bits: it must agree with comparing each channel to zero,
// for signed zeros, the smallest subnormals, infinities and NaNs of either sign.
#include <gtest/gtest.h>

#include <limits>

#include "core/spectrum.h"

namespace candela {
namespace {

TEST(SpectrumIsBlack, AgreesWithComparingEveryChannelToZero) {
  using L = std::numeric_limits<Float>;
  const Float values[] = {
      0.f,  -0.f,     L::denorm_min(), -L::denorm_min(), L::min(),       1.f,
      -1.f, L::max(), L::infinity(),   -L::infinity(),   L::quiet_NaN(), -L::quiet_NaN()};
  int black = 0;
  for (Float r : values)
    for (Float g : values)
      for (Float b : values) {
        Spectrum s(r, g, b);
        bool expected = r == 0 && g == 0 && b == 0;
        EXPECT_EQ(s.isBlack(), expected) << r << " " << g << " " << b;
        black += s.isBlack();
      }
  EXPECT_EQ(black, 8);  // the eight sign combinations of zero
}

}  // namespace
}  // namespace candela
