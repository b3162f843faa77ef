// pbrt-v3's 02sequence sampler: within its dimension budget every 1D dimension of a pixel's 2^k
// samples is stratified and every 2D one, the image plane included, a (0,k,2)-net; past the
// budget the values are unstratified; 1D and 2D dimensions are budgeted separately.
#include <gtest/gtest.h>

#include <vector>

#include "samplers/zero_two_sequence_sampler.h"
#include "support/point_set_measures.h"

namespace candela {
namespace {

// For each sample of the pixel: the image plane, then 1D and 2D dimensions alternately,
// `rounds` of each.
struct PixelDimensions {
  std::vector<Point2f> pixel;
  std::vector<std::vector<Float>> oneD;
  std::vector<std::vector<Point2f>> twoD;
};

PixelDimensions draw(Sampler& s, Point2i pixel, int n, int rounds) {
  PixelDimensions out;
  out.oneD.resize(size_t(rounds));
  out.twoD.resize(size_t(rounds));
  for (int i = 0; i < n; ++i) {
    s.startPixelSample(pixel, i);
    out.pixel.push_back(s.getPixel2D());
    for (int r = 0; r < rounds; ++r) {
      out.oneD[size_t(r)].push_back(s.get1D());
      out.twoD[size_t(r)].push_back(s.get2D());
    }
  }
  return out;
}

TEST(ZeroTwoSequenceSampler, StratifiedWithinTheDimensionBudget) {
  const int budget = 4;
  for (int k = 0; k <= 8; ++k) {
    const int n = 1 << k;
    ZeroTwoSequenceSampler sampler(n, budget, 77);
    EXPECT_EQ(sampler.samplesPerPixel(), n);
    EXPECT_EQ(sampler.dimensions(), budget);
    for (Point2i pixel : {Point2i(0, 0), Point2i(31, -2)}) {
      PixelDimensions d = draw(sampler, pixel, n, budget);
      EXPECT_TRUE(test::isZeroNet(d.pixel, k)) << "k " << k;
      // 1D dimensions 0..3; 2D dimensions 1..3 (the image plane is 2D dimension 0).
      for (int r = 0; r < budget; ++r) EXPECT_TRUE(test::isStratified1D(d.oneD[size_t(r)])) << r;
      for (int r = 0; r + 1 < budget; ++r)
        EXPECT_TRUE(test::isZeroNet(d.twoD[size_t(r)], k)) << "2D dimension " << r + 1;
    }
  }
}

TEST(ZeroTwoSequenceSampler, UnstratifiedPastTheBudget) {
  // dimensions = 2: 1D dimensions 2, 3 and 2D dimensions 2, 3 (rounds 2 and 3 of 1D, rounds 1
  // and 2 of 2D) are independent uniform values. 16 of them are stratified with probability
  // 16!/16^16 = 1.1e-6 per pixel; over 10 pixels at most one may be, by chance.
  ZeroTwoSequenceSampler sampler(16, 2, 5);
  int stratified1D = 0, nets2D = 0;
  for (int px = 0; px < 10; ++px) {
    PixelDimensions d = draw(sampler, {px, 0}, 16, 4);
    EXPECT_TRUE(test::isStratified1D(d.oneD[1]));
    EXPECT_TRUE(test::isZeroNet(d.twoD[0], 4));
    stratified1D += test::isStratified1D(d.oneD[2]) + test::isStratified1D(d.oneD[3]);
    nets2D += test::isZeroNet(d.twoD[1], 4) + test::isZeroNet(d.twoD[2], 4);
  }
  EXPECT_LE(stratified1D, 1);
  EXPECT_LE(nets2D, 1);
}

TEST(ZeroTwoSequenceSampler, EachBlockOfSamplesIsANetAndDimensionsArePairedDifferently) {
  ZeroTwoSequenceSampler sampler(8, 4, 3);
  // Samples 8..15 (asked for past the count) are the sequence's next net.
  std::vector<Point2f> second;
  for (int i = 8; i < 16; ++i) {
    sampler.startPixelSample({2, 2}, i);
    second.push_back(sampler.getPixel2D());
  }
  EXPECT_TRUE(test::isZeroNet(second, 3));
  // The stratum of 1D dimension 0 does not fix that of 1D dimension 1 the same way in every
  // pixel (the nested permutations pair the dimensions up at random).
  int identical = 0;
  for (int px = 0; px < 40; ++px) {
    PixelDimensions d = draw(sampler, {px, 0}, 8, 2);
    std::vector<int> a, b;
    for (int i = 0; i < 8; ++i) {
      a.push_back(int(d.oneD[0][size_t(i)] * 8));
      b.push_back(int(d.oneD[1][size_t(i)] * 8));
    }
    if (a == b) ++identical;
  }
  EXPECT_LT(identical, 2);
}

}  // namespace
}  // namespace candela
