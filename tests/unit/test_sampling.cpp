// Sampling routines against their pdfs (lrt draft §14-15): samples land where the pdf says
// (chi-square, fixed seed, significance 0.01), and each pdf integrates to one.
#include <gtest/gtest.h>

#include <functional>

#include "core/rng.h"
#include "core/sampling.h"
#include "support/tail_probabilities.h"

namespace candela {
namespace {

// Histogram of directions over (cos theta, phi) cells against the pdf integrated per cell.
void chiSquareDirections(const std::function<Vector3f(Point2f)>& sample,
                         const std::function<Float(const Vector3f&)>& pdf, const char* name) {
  const int nTheta = 16, nPhi = 32, n = 400000;
  std::vector<double> observed(nTheta * nPhi, 0), expected(nTheta * nPhi, 0);
  RNG rng(2024);
  auto cell = [&](const Vector3f& w) {
    Float cosT = clamp(w.z, -1, 1);
    int it = std::min(nTheta - 1, int((1 - cosT) / 2 * nTheta));
    Float phi = std::atan2(w.y, w.x);
    if (phi < 0) phi += 2 * kPi;
    int ip = std::min(nPhi - 1, int(phi / (2 * kPi) * nPhi));
    return it * nPhi + ip;
  };
  for (int i = 0; i < n; ++i) {
    Vector3f w = sample(Point2f(rng.uniformFloat(), rng.uniformFloat()));
    ASSERT_NEAR(w.length(), 1, 1e-4) << name;
    observed[cell(w)] += 1;
  }
  // Integrate the pdf over each cell in (cos theta, phi), which is uniform in solid angle.
  const int sub = 8;
  for (int it = 0; it < nTheta; ++it)
    for (int ip = 0; ip < nPhi; ++ip) {
      double s = 0;
      for (int a = 0; a < sub; ++a)
        for (int b = 0; b < sub; ++b) {
          double cosT = 1 - 2.0 * (it + (a + 0.5) / sub) / nTheta;
          double phi = 2 * M_PI * (ip + (b + 0.5) / sub) / nPhi;
          double sinT = std::sqrt(std::max(0.0, 1 - cosT * cosT));
          s += pdf(Vector3f(Float(sinT * std::cos(phi)), Float(sinT * std::sin(phi)), Float(cosT)));
        }
      double cellSolidAngle = (2.0 / nTheta) * (2 * M_PI / nPhi);
      expected[it * nPhi + ip] = s / (sub * sub) * cellSolidAngle * n;
    }
  // Pool cells with expected count below 5.
  double chi2 = 0, pooledObs = 0, pooledExp = 0;
  int dof = -1;
  for (size_t i = 0; i < observed.size(); ++i) {
    if (expected[i] < 5) {
      pooledObs += observed[i];
      pooledExp += expected[i];
      continue;
    }
    chi2 += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
    ++dof;
  }
  if (pooledExp >= 5) {
    chi2 += (pooledObs - pooledExp) * (pooledObs - pooledExp) / pooledExp;
    ++dof;
  } else {
    EXPECT_LT(pooledObs, 10) << name << ": samples where the pdf is ~0";
  }
  EXPECT_GT(stats::chiSquareSurvival(chi2, dof), 0.01)
      << name << " chi2 " << chi2 << " dof " << dof;
}

TEST(Sampling, DirectionSamplersMatchTheirPdfs) {
  chiSquareDirections(
      sampleUniformSphere, [](const Vector3f&) { return uniformSpherePdf(); }, "uniform sphere");
  chiSquareDirections(
      sampleUniformHemisphere,
      [](const Vector3f& w) { return w.z > 0 ? uniformHemispherePdf() : 0; }, "uniform hemisphere");
  chiSquareDirections(
      sampleCosineHemisphere,
      [](const Vector3f& w) { return w.z > 0 ? cosineHemispherePdf(w.z) : 0; },
      "cosine hemisphere");
  Float cosMax =
      0.75f;  // on a cell boundary: the midpoint quadrature assumes pdfs smooth within cells
  chiSquareDirections([&](Point2f u) { return sampleUniformCone(u, cosMax); },
                      [&](const Vector3f& w) { return w.z >= cosMax ? uniformConePdf(cosMax) : 0; },
                      "uniform cone");
}

TEST(Sampling, DiskAndTriangleSamplesAreUniform) {
  RNG rng(5);
  const int n = 200000;
  int inner = 0, firstQuadrant = 0, nearVertex0 = 0;
  for (int i = 0; i < n; ++i) {
    Point2f u(rng.uniformFloat(), rng.uniformFloat());
    Point2f d = sampleUniformDiskConcentric(u);
    ASSERT_LE(d.x * d.x + d.y * d.y, 1.0001f);
    inner += (d.x * d.x + d.y * d.y < 0.25f);
    firstQuadrant += (d.x > 0 && d.y > 0);
    Point2f b = sampleUniformTriangle(u);
    ASSERT_GE(b.x, 0);
    ASSERT_GE(b.y, 0);
    ASSERT_LE(b.x + b.y, 1.0001f);
    nearVertex0 += (b.x > 0.5f);  // the corner triangle at vertex 0 holds 1/4 of the area
  }
  // Binomial standard errors are ~0.001; 5 of them.
  EXPECT_NEAR(inner / double(n), 0.25, 0.005);
  EXPECT_NEAR(firstQuadrant / double(n), 0.25, 0.005);
  EXPECT_NEAR(nearVertex0 / double(n), 0.25, 0.005);
  EXPECT_EQ(sampleUniformDiskConcentric(Point2f(0.5f, 0.5f)), Point2f(0, 0));
}

TEST(Sampling, ConcentricDiskIsShirleyChiusMapToFloatPrecision) {
  // The map's sine and cosine come from series on [-pi/4, pi/4]: against the map computed with
  // the library's functions in double, within 2e-7 of the radius everywhere.
  for (int i = 0; i <= 400; ++i)
    for (int j = 0; j <= 400; ++j) {
      Point2f u(Float(i) / 400 * kOneMinusEpsilon, Float(j) / 400 * kOneMinusEpsilon);
      double ox = 2.0 * u.x - 1, oy = 2.0 * u.y - 1;
      if (ox == 0 && oy == 0) continue;
      double r = std::abs(ox) > std::abs(oy) ? ox : oy;
      double theta =
          std::abs(ox) > std::abs(oy) ? kPiOver4 * (oy / ox) : kPiOver2 - kPiOver4 * (ox / oy);
      Point2f d = sampleUniformDiskConcentric(u);
      ASSERT_NEAR(d.x, r * std::cos(theta), 2e-7 * std::abs(r)) << u.x << " " << u.y;
      ASSERT_NEAR(d.y, r * std::sin(theta), 2e-7 * std::abs(r)) << u.x << " " << u.y;
    }
}

TEST(Sampling, PowerHeuristicWeightsSumToOne) {
  for (Float a : {0.1f, 1.f, 7.f, 1e6f})
    for (Float b : {0.f, 0.5f, 3.f, 1e-6f})
      EXPECT_NEAR(powerHeuristic(1, a, 1, b) + powerHeuristic(1, b, 1, a), 1, 1e-6);
  EXPECT_EQ(powerHeuristic(1, 0, 1, 0), 0);
}

TEST(Distribution1D, SamplesFollowTheFunction) {
  Distribution1D d({1, 0, 3, 4});
  EXPECT_FLOAT_EQ(d.integral(), 2);
  RNG rng(11);
  std::vector<int> counts(4, 0);
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    Float pdf;
    int off;
    Float x = d.sampleContinuous(rng.uniformFloat(), &pdf, &off);
    ASSERT_GE(x, 0);
    ASSERT_LT(x, 1);
    ASSERT_EQ(off, int(x * 4));
    ASSERT_FLOAT_EQ(pdf, d.func(off) / d.integral());
    ++counts[off];
  }
  EXPECT_EQ(counts[1], 0);
  EXPECT_NEAR(counts[0] / double(n), 0.125, 0.005);
  EXPECT_NEAR(counts[3] / double(n), 0.5, 0.005);
  EXPECT_FLOAT_EQ(d.discretePmf(2), 3.f / 8);
}

TEST(Distribution2D, PdfMatchesTheFunctionAndIntegratesToOne) {
  std::vector<Float> f = {1, 2, 0, 4, 1, 1, 3, 0, 2};  // 3 x 3
  Distribution2D d(f, 3, 3);
  double integral = 0;
  for (int v = 0; v < 3; ++v)
    for (int u = 0; u < 3; ++u) integral += d.pdf(Point2f((u + 0.5f) / 3, (v + 0.5f) / 3)) / 9;
  EXPECT_NEAR(integral, 1, 1e-5);
  RNG rng(1);
  for (int i = 0; i < 10000; ++i) {
    Float pdf;
    Point2f p = d.sampleContinuous(Point2f(rng.uniformFloat(), rng.uniformFloat()), &pdf);
    ASSERT_NEAR(pdf, d.pdf(p), 1e-4);
    ASSERT_GT(pdf, 0);
  }
}

}  // namespace
}  // namespace candela
