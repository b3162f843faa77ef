// The Sobol' generator matrices against the sequence's published first points, and the
// per-pixel Owen-scrambled Sobol' sampler: its image-plane points are (0,k,2)-nets, every
// dimension is stratified, and scrambles differ between pixels and seeds.
#include <gtest/gtest.h>

#include <set>
#include <vector>

#include "samplers/owen_scramble.h"
#include "samplers/sobol_matrices.h"
#include "samplers/sobol_sampler.h"
#include "samplers/zero_two_sequence.h"
#include "support/point_set_measures.h"

namespace candela {
namespace {

double unit(uint32_t bits) { return double(bits) * 0x1p-32; }

TEST(SobolMatrices, FirstPointsAreJoeAndKuosSequence) {
  // Joe & Kuo list the first points of their sequence in Gray-code order, in which point n is
  // the one of natural index n ^ (n >> 1): (0,0,0), (.5,.5,.5), (.75,.25,.25), ...
  const double expected[10][3] = {{0, 0, 0},
                                  {0.5, 0.5, 0.5},
                                  {0.75, 0.25, 0.25},
                                  {0.25, 0.75, 0.75},
                                  {0.375, 0.375, 0.625},
                                  {0.875, 0.875, 0.125},
                                  {0.625, 0.125, 0.875},
                                  {0.125, 0.625, 0.375},
                                  {0.1875, 0.3125, 0.9375},
                                  {0.6875, 0.8125, 0.4375}};
  for (uint32_t n = 0; n < 10; ++n)
    for (int d = 0; d < 3; ++d)
      EXPECT_EQ(unit(sobolBits(n ^ (n >> 1), d)), expected[n][d]) << "point " << n << " dim " << d;
}

TEST(SobolMatrices, SecondDimensionIsTheZeroTwoSequences) {
  for (uint32_t n = 0; n < 5000; ++n) {
    ASSERT_EQ(sobolBits(n, 0), vanDerCorputBits(n, 0)) << n;
    ASSERT_EQ(sobolBits(n, 1), sobol2Bits(n, 0)) << n;
  }
}

TEST(SobolMatrices, EveryDimensionIsStratifiedAndDimensionsDiffer) {
  // The first 2^k values of each coordinate are exactly the multiples of 2^-k (for k = 10, the
  // top 10 bits all differ); and no two dimensions are the same sequence.
  std::set<std::vector<uint32_t>> sequences;
  for (int d = 0; d < kSobolDimensions; ++d) {
    std::set<uint32_t> top;
    std::vector<uint32_t> values;
    for (uint32_t n = 0; n < 1024; ++n) {
      top.insert(sobolBits(n, d) >> 22);
      values.push_back(sobolBits(n, d));
    }
    EXPECT_EQ(top.size(), 1024u) << "dimension " << d;
    sequences.insert(values);
  }
  EXPECT_EQ(sequences.size(), size_t(kSobolDimensions));
}

TEST(OwenScramble, KeepsElementaryIntervalsAndChangesWithTheSeed) {
  for (uint32_t seed : {0u, 1u, 0xdeadbeefu}) {
    for (int k : {4, 7}) {
      std::vector<Point2f> points;
      for (uint32_t n = 0; n < (1u << k); ++n)
        points.emplace_back(bitsToUnitFloat(owenScrambleBits(sobolBits(n, 0), seed)),
                            bitsToUnitFloat(owenScrambleBits(sobolBits(n, 1), seed * 7 + 1)));
      EXPECT_TRUE(test::isZeroNet(points, k)) << "seed " << seed << " k " << k;
    }
  }
  // A permutation of the values: the 2^12 values stay distinct, and seeds change them.
  std::set<uint32_t> distinct;
  int unchanged = 0;
  for (uint32_t v = 0; v < 4096; ++v) {
    distinct.insert(owenScrambleBits(v << 20, 12345u));
    if (owenScrambleBits(v << 20, 1u) == owenScrambleBits(v << 20, 2u)) ++unchanged;
  }
  EXPECT_EQ(distinct.size(), 4096u);
  EXPECT_LT(unchanged, 4096 / 8);
}

std::vector<Point2f> pixelPoints(Sampler& s, Point2i pixel, int n) {
  std::vector<Point2f> points;
  for (int i = 0; i < n; ++i) {
    s.startPixelSample(pixel, i);
    points.push_back(s.getPixel2D());
  }
  return points;
}

TEST(SobolSampler, PixelSamplesAreNetsAndEveryDimensionStratified) {
  for (int k = 0; k <= 8; ++k) {
    const int n = 1 << k;
    for (uint64_t seed : {1u, 2u}) {
      SobolSampler sampler(n, seed);
      for (Point2i pixel : {Point2i(0, 0), Point2i(13, 7), Point2i(-3, 400)}) {
        EXPECT_TRUE(test::isZeroNet(pixelPoints(sampler, pixel, n), k))
            << "k " << k << " pixel " << pixel.x << "," << pixel.y;
        // The next dimensions: 1D, 2D, 1D, each coordinate stratified, the 2D one a net.
        std::vector<Float> a, c;
        std::vector<Point2f> b;
        for (int i = 0; i < n; ++i) {
          sampler.startPixelSample(pixel, i);
          a.push_back(sampler.get1D());
          b.push_back(sampler.get2D());
          c.push_back(sampler.get1D());
        }
        EXPECT_TRUE(test::isStratified1D(a)) << k;
        EXPECT_TRUE(test::isStratified1D(c)) << k;
        // Sobol' dimensions 3 and 4 are not a (0,2)-net on their own for every k, but each is
        // stratified.
        std::vector<Float> bx, by;
        for (Point2f p : b) {
          bx.push_back(p.x);
          by.push_back(p.y);
        }
        EXPECT_TRUE(test::isStratified1D(bx)) << k;
        EXPECT_TRUE(test::isStratified1D(by)) << k;
      }
    }
  }
}

TEST(SobolSampler, PixelsAndSeedsScrambleDifferently) {
  SobolSampler a(16, 5), b(16, 6);
  auto pa = pixelPoints(a, {4, 4}, 16);
  auto pa2 = pixelPoints(a, {5, 4}, 16);
  auto pb = pixelPoints(b, {4, 4}, 16);
  EXPECT_NE(pa[0].x, pa2[0].x);
  EXPECT_NE(pa[0].x, pb[0].x);
  EXPECT_EQ(pixelPoints(*a.clone(), {4, 4}, 16)[3].y, pa[3].y);
}

TEST(SobolSampler, PastTheTableValuesAreUniformAndDiffer) {
  // Dimensions 2 .. 127 come from the table; the 1D draws after 126 of them are hashed values.
  SobolSampler sampler(4, 3);
  double sum = 0;
  int count = 0;
  std::set<Float> seen;
  for (int px = 0; px < 200; ++px)
    for (int i = 0; i < 4; ++i) {
      sampler.startPixelSample(Point2i(px, 1), i);
      for (int d = 2; d < kSobolDimensions; ++d) sampler.get1D();
      for (int d = 0; d < 8; ++d) {
        Float v = sampler.get1D();
        ASSERT_GE(v, 0.f);
        ASSERT_LT(v, 1.f);
        sum += v;
        seen.insert(v);
        ++count;
      }
    }
  // 6400 values: the mean's standard error is 0.0036; 0.02 is 5.6 of them.
  EXPECT_NEAR(sum / count, 0.5, 0.02);
  EXPECT_GT(seen.size(), size_t(count * 0.99));
}

}  // namespace
}  // namespace candela
