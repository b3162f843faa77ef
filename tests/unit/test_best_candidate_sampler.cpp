// The best-candidate pattern and sampler: the pattern's minimum distance far above a uniform
// random set's, a fixed count per cell, the image plane tiled with period T, stratified 1D
// dimensions, values in [0, 1).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/rng.h"
#include "samplers/best_candidate_pattern.h"
#include "samplers/best_candidate_sampler.h"

namespace candela {
namespace {

double randomMinimumDistance(int n, uint64_t seed) {
  RNG rng(seed);
  std::vector<Point2f> p;
  for (int i = 0; i < n; ++i) p.emplace_back(rng.uniformFloat(), rng.uniformFloat());
  double best = 1;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      double dx = std::abs(p[i].x - p[j].x), dy = std::abs(p[i].y - p[j].y);
      dx = std::min(dx, 1 - dx);
      dy = std::min(dy, 1 - dy);
      best = std::min(best, std::sqrt(dx * dx + dy * dy));
    }
  return best;
}

TEST(BestCandidatePattern, MinimumDistanceFarAboveRandom) {
  // N points on the unit torus. For a uniform random set, P(min distance >= r) is about
  // exp(-pi r^2 N^2 / 2); at r = 0.45 / sqrt(N) that is exp(-0.318 N): below e^-81 for N = 256
  // and e^-1300 for N = 4096, so a pattern meeting the bound is far from random. (A hexagonal
  // packing reaches 1.07 / sqrt(N); these patterns measure 0.52-0.76 / sqrt(N).)
  struct Case {
    int cells, perCell;
  };
  for (Case c : {Case{64, 1}, Case{32, 4}, Case{16, 16}, Case{8, 64}, Case{1, 256}}) {
    BestCandidatePattern pattern(c.cells, c.perCell, 17);
    int n = c.cells * c.cells * c.perCell;
    double bound = 0.45 / std::sqrt(double(n));
    double minDist = pattern.minimumDistance();
    EXPECT_GT(minDist, bound) << c.cells << " cells x " << c.perCell;
    // The same test fails for random points: their minimum is around 0.66 / N.
    EXPECT_LT(randomMinimumDistance(n, 5), bound);
    for (int cy = 0; cy < c.cells; ++cy)
      for (int cx = 0; cx < c.cells; ++cx)
        for (int k = 0; k < c.perCell; ++k) {
          Point2f u = pattern.cellPoint(cx, cy, k);
          ASSERT_TRUE(u.x >= 0 && u.x < 1 && u.y >= 0 && u.y < 1);
        }
  }
}

TEST(BestCandidatePattern, DeterministicPerSeed) {
  BestCandidatePattern a(8, 4, 3), b(8, 4, 3), c(8, 4, 4);
  int same = 0;
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(a.cellPoint(5, 2, k).x, b.cellPoint(5, 2, k).x);
    EXPECT_EQ(a.cellPoint(5, 2, k).y, b.cellPoint(5, 2, k).y);
    same += a.cellPoint(5, 2, k).x == c.cellPoint(5, 2, k).x;
  }
  EXPECT_LT(same, 4);
}

TEST(BestCandidateSampler, ImagePlaneTilesTheImageWithThePattern) {
  const int spp = 4;
  BestCandidateSampler sampler(spp, 21);
  const BestCandidatePattern& pattern = sampler.imagePattern();
  int t = pattern.cellsPerSide();
  EXPECT_EQ(t, 32);  // 32 x 32 pixels x 4 samples = 4096 points
  for (Point2i pixel : {Point2i(0, 0), Point2i(5, 40), Point2i(100, 7)})
    for (int s = 0; s < spp; ++s) {
      sampler.startPixelSample(pixel, s);
      Point2f p = sampler.getPixel2D();
      Point2f q = pattern.cellPoint(pixel.x % t, pixel.y % t, s);
      EXPECT_EQ(p.x, q.x);
      EXPECT_EQ(p.y, q.y);
      sampler.startPixelSample(Point2i(pixel.x + t, pixel.y + 2 * t), s);
      EXPECT_EQ(sampler.getPixel2D().x, p.x);
    }
}

TEST(BestCandidateSampler, OtherDimensionsStratifiedAndShiftedPerPixel) {
  const int spp = 16;
  BestCandidateSampler sampler(spp, 2);
  std::vector<Float> firstPixel;
  for (Point2i pixel : {Point2i(1, 1), Point2i(2, 1)}) {
    std::vector<Float> values;
    double minDist2D = 1;
    std::vector<Point2f> pts;
    for (int s = 0; s < spp; ++s) {
      sampler.startPixelSample(pixel, s);
      Float v = sampler.get1D();
      Point2f p = sampler.get2D();
      ASSERT_TRUE(v >= 0 && v < 1 && p.x >= 0 && p.x < 1 && p.y >= 0 && p.y < 1);
      values.push_back(v);
      pts.push_back(p);
    }
    // The lattice i/n shifted by u mod 1: one value in every interval [u + j/n, u + (j+1)/n)
    // mod 1, i.e. sorted neighbours exactly 1/n apart.
    std::sort(values.begin(), values.end());
    for (int i = 1; i < spp; ++i) EXPECT_NEAR(values[i] - values[i - 1], 1.f / spp, 1e-5);
    // The 2D points keep the unit pattern's toroidal spacing under the shift.
    for (size_t i = 0; i < pts.size(); ++i)
      for (size_t j = i + 1; j < pts.size(); ++j) {
        double dx = std::abs(pts[i].x - pts[j].x), dy = std::abs(pts[i].y - pts[j].y);
        dx = std::min(dx, 1 - dx);
        dy = std::min(dy, 1 - dy);
        minDist2D = std::min(minDist2D, std::sqrt(dx * dx + dy * dy));
      }
    EXPECT_GT(minDist2D, 0.5 / std::sqrt(double(spp)));
    if (firstPixel.empty())
      firstPixel = values;
    else
      EXPECT_NE(firstPixel, values);  // a different shift per pixel
  }
}

}  // namespace
}  // namespace candela
