// The star discrepancy of a pixel's image-plane samples, averaged over pixels, for pbrt-v3's
// (0,2)-net samplers against independent uniform points. Measured (seed 3, 8 pixels):
//   n      random   02sequence  maxmindist  sobol
//   16     0.324    0.120       0.101       0.124
//   64     0.140    0.038       0.036       0.041
//   256    0.062    0.012       0.012       0.013
// A (0,m,2)-net's is O(m / 2^m); random points' is O(1 / sqrt(n)) (Niederreiter 1992, ch. 2-4).
// The test asks for less than half the random points' at every n.
#include <gtest/gtest.h>

#include <iostream>
#include <string>
#include <vector>

#include "samplers/sampler.h"
#include "support/point_set_measures.h"

namespace candela {
namespace {

double meanPixelDiscrepancy(const std::string& name, int n) {
  auto sampler = createSampler(name, ParamSet(), 3, n, FileLoc{});
  double sum = 0;
  const int pixels = 8;
  for (int px = 0; px < pixels; ++px) {
    std::vector<Point2f> points;
    for (int i = 0; i < n; ++i) {
      sampler->startPixelSample({px, 2 * px + 1}, i);
      points.push_back(sampler->getPixel2D());
    }
    sum += test::starDiscrepancy(points);
  }
  return sum / pixels;
}

TEST(SamplerDiscrepancy, NetSamplersHalveTheRandomPointsStarDiscrepancy) {
  for (int n : {16, 64, 256}) {
    double random = meanPixelDiscrepancy("random", n);
    std::cout << "n " << n << ": random " << random;
    for (const char* name : {"02sequence", "maxmindist", "sobol"}) {
      double d = meanPixelDiscrepancy(name, n);
      std::cout << ", " << name << " " << d;
      EXPECT_LT(d, 0.5 * random) << name << " n " << n;
    }
    std::cout << "\n";
  }
}

}  // namespace
}  // namespace candela
