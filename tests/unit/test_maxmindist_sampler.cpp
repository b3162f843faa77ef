// The max-min-distance generator matrices and sampler: each matrix gives a (0,m,2)-net; for
// m <= 4 its smallest toroidal distance is the largest that any generator matrix giving a
// (0,m,2)-net of the form (i / 2^m, C i) attains (an exhaustive search, as Grünschloß et al.'s
// for small m); for larger m it exceeds that of the (0,2)-sequence's net; the sampler's
// image-plane points are the net in a per-pixel order and its other dimensions the 02sequence
// sampler's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "samplers/max_min_dist_matrices.h"
#include "samplers/maxmindist_sampler.h"
#include "samplers/zero_two_sequence.h"
#include "samplers/zero_two_sequence_sampler.h"
#include "support/point_set_measures.h"

namespace candela {
namespace {

// The points (i / 2^m, C i) for C given as top-aligned columns.
std::vector<Point2f> netOf(int m, const std::vector<uint32_t>& columns) {
  std::vector<Point2f> points;
  for (uint32_t i = 0; i < (1u << m); ++i) {
    uint32_t y = 0;
    for (int j = 0; j < m; ++j)
      if ((i >> j) & 1u) y ^= columns[size_t(j)];
    points.emplace_back(std::ldexp(Float(i), -m), bitsToUnitFloat(y));
  }
  return points;
}

std::vector<Point2f> maxMinDistNet(int m) {
  std::vector<Point2f> points;
  for (uint32_t i = 0; i < (1u << m); ++i)
    points.emplace_back(std::ldexp(Float(i), -m), bitsToUnitFloat(maxMinDistBits(i, m)));
  return points;
}

TEST(MaxMinDistMatrices, EveryMatrixGivesAZeroNet) {
  for (int m = 0; m <= kMaxMinDistLog2Max; ++m)
    EXPECT_TRUE(test::isZeroNet(maxMinDistNet(m), m)) << "m " << m;
}

TEST(MaxMinDistMatrices, SmallNetsHaveTheLargestMinimumDistanceAnyNetMatrixGives) {
  for (int m = 1; m <= 4; ++m) {
    // Every m x m matrix over GF(2): 2^(m^2) of them, 65536 for m = 4.
    double best = 0;
    for (uint32_t bits = 0; bits < (1u << (m * m)); ++bits) {
      std::vector<uint32_t> columns;
      for (int j = 0; j < m; ++j)
        columns.push_back(((bits >> (j * m)) & ((1u << m) - 1)) << (32 - m));
      std::vector<Point2f> points = netOf(m, columns);
      if (test::isZeroNet(points, m)) best = std::max(best, test::toroidalMinDistance(points));
    }
    double table = test::toroidalMinDistance(maxMinDistNet(m));
    EXPECT_EQ(table, best) << "m " << m;
    EXPECT_GT(best, 0);
  }
}

TEST(MaxMinDistMatrices, LargerNetsSpreadFartherThanTheZeroTwoSequence) {
  // The (0,2)-sequence's first 2^m points, (Phi_2(i), Sobol'_2(i)), are a (0,m,2)-net too.
  for (int m = 5; m <= 10; ++m) {
    std::vector<Point2f> zeroTwo;
    for (uint32_t i = 0; i < (1u << m); ++i)
      zeroTwo.emplace_back(bitsToUnitFloat(vanDerCorputBits(i, 0)),
                           bitsToUnitFloat(sobol2Bits(i, 0)));
    ASSERT_TRUE(test::isZeroNet(zeroTwo, m));
    EXPECT_GT(test::toroidalMinDistance(maxMinDistNet(m)), test::toroidalMinDistance(zeroTwo))
        << "m " << m;
  }
}

TEST(MaxMinDistSampler, PixelSamplesAreTheNetInAPerPixelOrder) {
  const int m = 5, n = 1 << m;
  MaxMinDistSampler sampler(n, 4, 11);
  // The net moved to its cells' centres, by half of 1/2^m in each coordinate.
  const Float half = std::ldexp(Float(1), -(m + 1));
  auto key = [](Point2f p) { return std::make_pair(p.x, p.y); };
  std::set<std::pair<Float, Float>> expected;
  for (Point2f p : maxMinDistNet(m)) expected.insert({p.x + half, p.y + half});
  std::set<std::vector<std::pair<Float, Float>>> orders;
  for (int px = 0; px < 6; ++px)
    for (int block = 0; block < 2; ++block) {
      std::vector<std::pair<Float, Float>> order;
      for (int i = 0; i < n; ++i) {
        sampler.startPixelSample({px, 3}, block * n + i);
        order.push_back(key(sampler.getPixel2D()));
      }
      EXPECT_EQ((std::set<std::pair<Float, Float>>(order.begin(), order.end())), expected);
      orders.insert(order);
    }
  EXPECT_EQ(orders.size(), 12u);
  // Still a net, with the net's distances, and centred on the pixel on average.
  std::vector<Point2f> points;
  double meanX = 0, meanY = 0;
  for (int i = 0; i < n; ++i) {
    sampler.startPixelSample({1, 1}, i);
    points.push_back(sampler.getPixel2D());
    meanX += points.back().x / n;
    meanY += points.back().y / n;
  }
  EXPECT_TRUE(test::isZeroNet(points, m));
  EXPECT_NEAR(test::toroidalMinDistance(points), test::toroidalMinDistance(maxMinDistNet(m)), 1e-6);
  EXPECT_EQ(meanX, 0.5);
  EXPECT_EQ(meanY, 0.5);
}

TEST(MaxMinDistSampler, OtherDimensionsAreTheZeroTwoSequenceSamplers) {
  MaxMinDistSampler maxmin(16, 3, 21);
  ZeroTwoSequenceSampler zeroTwo(16, 3, 21);
  for (int i = 0; i < 16; ++i) {
    maxmin.startPixelSample({7, 8}, i);
    zeroTwo.startPixelSample({7, 8}, i);
    for (int d = 0; d < 5; ++d) {
      ASSERT_EQ(maxmin.get1D(), zeroTwo.get1D());
      Point2f a = maxmin.get2D(), b = zeroTwo.get2D();
      ASSERT_EQ(a.x, b.x);
      ASSERT_EQ(a.y, b.y);
    }
  }
  EXPECT_EQ(maxmin.clone()->samplesPerPixel(), 16);
}

}  // namespace
}  // namespace candela
