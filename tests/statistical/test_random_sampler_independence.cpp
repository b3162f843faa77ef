// The random sampler's values are independent uniforms: over 32 x 32 pixels x 256 samples (seed
// 3), each of 24 dimensions fills 64 equal bins evenly, and an 8 x 8 grid evenly for each pair a
// correlation or a lattice would show in: consecutive dimensions (d, d + 1), the two halves of a
// get2D, and the same dimension in consecutive samples of a pixel. Each histogram is a chi-square
// goodness-of-fit test (63 degrees of freedom), family-wise significance 0.01 over all of them
// with a Šidák correction. Values lie in [0, 1). A stream where one value in 20 repeats the
// previous dimension's (keeping every dimension uniform) fails the pair test.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include "samplers/random_sampler.h"
#include "support/tail_probabilities.h"

namespace candela {
namespace {

constexpr int kSide = 32, kSpp = 256, kDimensions = 24;
constexpr int kSamples = kSide * kSide * kSpp;
// 24 one-dimensional histograms, 23 consecutive-dimension pairs, one get2D pair and 24
// consecutive-sample pairs.
constexpr int kHistograms = kDimensions + (kDimensions - 1) + 1 + kDimensions;

// Chi-square of 64 counts against equal expectations, as its survival probability.
double uniformityP(const std::array<long, 64>& counts) {
  long total = 0;
  for (long c : counts) total += c;
  double expected = double(total) / 64, chi2 = 0;
  for (long c : counts) chi2 += (c - expected) * (c - expected) / expected;
  return stats::chiSquareSurvival(chi2, 63);
}

int bin64(Float u) { return std::min(63, int(u * 64)); }
int cell8x8(Float u, Float v) { return std::min(7, int(u * 8)) * 8 + std::min(7, int(v * 8)); }

// The values of one pixel sample: a get2D, then get1D for the remaining dimensions (the two
// halves of the get2D count as dimensions 0 and 1).
using SampleValues = std::array<Float, kDimensions>;
using DrawSample = std::function<SampleValues(const Point2i&, int)>;

struct IndependenceFigures {
  double smallestP = 1;
  std::string where;
  bool allInUnitInterval = true;
};

IndependenceFigures measureIndependence(const DrawSample& draw) {
  std::vector<std::array<long, 64>> single(kDimensions), next(kDimensions - 1),
      sameDimension(kDimensions);
  std::array<long, 64> halves{};
  for (auto* v : {&single, &next, &sameDimension})
    for (auto& h : *v) h.fill(0);
  IndependenceFigures f;
  for (int y = 0; y < kSide; ++y)
    for (int x = 0; x < kSide; ++x) {
      SampleValues previous{};
      for (int i = 0; i < kSpp; ++i) {
        SampleValues u = draw(Point2i(x, y), i);
        for (int d = 0; d < kDimensions; ++d) {
          f.allInUnitInterval &= u[d] >= 0 && u[d] < 1;
          ++single[d][bin64(u[d])];
          if (d + 1 < kDimensions) ++next[d][cell8x8(u[d], u[d + 1])];
          if (i > 0) ++sameDimension[d][cell8x8(previous[d], u[d])];
        }
        ++halves[cell8x8(u[0], u[1])];
        previous = u;
      }
    }
  auto consider = [&](const std::array<long, 64>& h, const std::string& what) {
    double p = uniformityP(h);
    if (p < f.smallestP) {
      f.smallestP = p;
      f.where = what;
    }
  };
  for (int d = 0; d < kDimensions; ++d) {
    consider(single[d], "dimension " + std::to_string(d));
    consider(sameDimension[d], "dimension " + std::to_string(d) + " in consecutive samples");
    if (d + 1 < kDimensions)
      consider(next[d], "dimensions " + std::to_string(d) + ", " + std::to_string(d + 1));
  }
  consider(halves, "the halves of get2D");
  return f;
}

SampleValues drawFrom(Sampler& sampler, const Point2i& pixel, int index) {
  sampler.startPixelSample(pixel, index);
  SampleValues u;
  Point2f p = sampler.get2D();
  u[0] = p.x;
  u[1] = p.y;
  for (int d = 2; d < kDimensions; ++d) u[d] = sampler.get1D();
  return u;
}

TEST(RandomSamplerIndependence, DimensionsAndSamplesAreIndependentUniforms) {
  RandomSampler sampler(kSpp, 3);
  IndependenceFigures f = measureIndependence(
      [&](const Point2i& pixel, int index) { return drawFrom(sampler, pixel, index); });
  std::cout << "smallest p " << f.smallestP << " (" << f.where << ")\n";
  EXPECT_TRUE(f.allInUnitInterval);
  EXPECT_GT(f.smallestP, stats::sidak(0.01, kHistograms)) << f.where;
}

// The check can fail: one value in 20 repeating the previous dimension's.
TEST(RandomSamplerIndependence, RepeatedValuesAreFound) {
  RandomSampler sampler(kSpp, 3);
  IndependenceFigures f = measureIndependence([&](const Point2i& pixel, int index) {
    SampleValues u = drawFrom(sampler, pixel, index);
    for (int d = 1; d < kDimensions; ++d)
      if ((index + d) % 20 == 0) u[d] = u[d - 1];
    return u;
  });
  std::cout << "smallest p " << f.smallestP << " (" << f.where << ")\n";
  EXPECT_LT(f.smallestP, stats::sidak(0.01, kHistograms));
}

}  // namespace
}  // namespace candela
