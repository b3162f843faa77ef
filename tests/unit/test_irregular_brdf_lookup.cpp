// The irregular measured BRDF's lookup (pbrt 2e §8.6) on data sets with known answers: samples of
// smooth BRDFs at random direction pairs are reproduced at other pairs, queries 0.5 degrees apart
// give nearby values, f is reciprocal and two-sided, and the search radius stops growing (and f
// is 0) exactly where the book's doubling loop stops. All random numbers come from fixed seeds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "reflection/irregular_brdf.h"

namespace candela {
namespace {

using Brdf = std::function<double(const Vector3f& wo, const Vector3f& wi)>;

// Uniform over the part of the upper hemisphere with z >= minZ.
Vector3f randomDirection(RNG& rng, Float minZ = 0) {
  Float z = minZ + (1 - minZ) * rng.uniformFloat(), phi = 2 * kPi * rng.uniformFloat();
  Float s = std::sqrt(std::max(Float(0), 1 - z * z));
  return {s * std::cos(phi), s * std::sin(phi), z};
}

Vector3f fromDegrees(double theta, double phi) {
  double t = theta * M_PI / 180, p = phi * M_PI / 180;
  return Vector3f(Float(std::sin(t) * std::cos(p)), Float(std::sin(t) * std::sin(p)),
                  Float(std::cos(t)));
}

// A diffuse term plus a Phong lobe about the mirror direction: smooth, reciprocal, isotropic.
double phongLike(const Vector3f& wo, const Vector3f& wi) {
  const double n = 4;
  double c = std::max(0.0, double(dot(reflectAboutNormal(wo), wi)));
  return 0.2 / M_PI + 0.5 * (n + 2) / (2 * M_PI) * std::pow(c, n);
}

// n samples of brdf at uniformly random direction pairs (grey: the same in every channel).
IrregularBrdfTable sampledTable(int n, uint64_t seed, const Brdf& brdf) {
  RNG rng(seed);
  std::vector<IrregularBrdfSample> samples;
  for (int i = 0; i < n; ++i) {
    Vector3f wi = randomDirection(rng), wo = randomDirection(rng);
    samples.push_back({wi, wo, Spectrum(Float(brdf(wo, wi)))});
  }
  return IrregularBrdfTable(std::move(samples));
}

Float distance2(const PointKdTree<3>::Point& a, const PointKdTree<3>::Point& b) {
  Float d = 0;
  for (int i = 0; i < 3; ++i) d += (a[i] - b[i]) * (a[i] - b[i]);
  return d;
}

// The book's loop taken literally (pbrt 2e §8.6): search every sample at each squared radius
// from 0.001, doubling, until more than two are inside or the radius searched exceeds 1.5.
IrregularBrdfEstimate bookLoop(const IrregularBrdfTable& t, const Vector3f& wo,
                               const Vector3f& wi) {
  IrregularBrdfEstimate e;
  PointKdTree<3>::Point q = IrregularBrdfTable::reduce(wi, wo);
  for (Float r2 = 0.001f;; r2 *= 2) {
    double sum = 0, weights = 0;
    int found = 0;
    for (const IrregularBrdfSample& s : t.samples()) {
      Float d2 = distance2(q, IrregularBrdfTable::reduce(s.wi, s.wo));
      if (d2 >= r2) continue;
      double w = std::exp(-100.0 * d2);
      sum += w * s.value[0];
      weights += w;
      ++found;
    }
    if (found > 2 || r2 > 1.5f) {
      e.found = found;
      e.radius2 = r2;
      e.value = Spectrum(found ? Float(std::max(0.0, sum) / weights) : 0);
      return e;
    }
  }
}

TEST(IrregularBrdfLookup, ReductionIsMarschnersPoint) {
  // theta_i 30, theta_o 60 degrees, azimuths 170 and -100: the difference 270 folds to 90.
  auto p = IrregularBrdfTable::reduce(fromDegrees(30, 170), fromDegrees(60, -100));
  EXPECT_NEAR(p[0], std::sin(M_PI / 6) * std::sin(M_PI / 3), 1e-6);
  EXPECT_NEAR(p[1], 0.5, 1e-6);
  EXPECT_NEAR(p[2], std::cos(M_PI / 6) * std::cos(M_PI / 3), 1e-6);
  // Symmetric, blind to a common rotation about the normal and to mirroring below the surface.
  Vector3f a = fromDegrees(50, 20), b = fromDegrees(20, 200);
  auto p0 = IrregularBrdfTable::reduce(a, b);
  EXPECT_EQ(p0, IrregularBrdfTable::reduce(b, a));
  auto p1 = IrregularBrdfTable::reduce(fromDegrees(50, 95), fromDegrees(20, 275));
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(p0[i], p1[i], 1e-6);
  EXPECT_EQ(p0, IrregularBrdfTable::reduce(otherHemisphere(a), otherHemisphere(b)));
  // A pole has azimuth 0 whatever the signs of its zeros.
  EXPECT_EQ(IrregularBrdfTable::reduce(Vector3f(-0.f, -0.f, 1), fromDegrees(40, 90))[1],
            IrregularBrdfTable::reduce(Vector3f(0, 0, 1), fromDegrees(40, 90))[1]);
}

TEST(IrregularBrdfLookup, ConstantDataAreReproducedExactly) {
  // A Lambertian data set: every weighted mean of equal values is that value, to rounding.
  const double kd = 0.3 / M_PI;
  IrregularBrdfTable t =
      sampledTable(1500, 3, [&](const Vector3f&, const Vector3f&) { return kd; });
  RNG rng(4);
  for (int i = 0; i < 1000; ++i) {
    Vector3f wo = randomDirection(rng), wi = randomDirection(rng);
    EXPECT_NEAR(t.lookup(wo, wi)[0], kd, 1e-6 * kd);
  }
}

TEST(IrregularBrdfLookup, SmoothBrdfIsReproducedAtOtherPairs) {
  // 4000 random pairs of the Phong-like BRDF (peak 1.0, floor 0.064); queries at 1000 other
  // random pairs away from grazing (theta < 80 degrees), where the data surround the query. The
  // estimate is a local mean over about the three nearest samples, so its error is the lobe's
  // variation across that neighbourhood: measured rms 4.6%, worst 34% (on the lobe's flank).
  IrregularBrdfTable t = sampledTable(4000, 5, phongLike);
  RNG rng(6);
  double sumSq = 0, worst = 0;
  const int n = 1000;
  for (int i = 0; i < n; ++i) {
    Vector3f wo = randomDirection(rng, 0.18f), wi = randomDirection(rng, 0.18f);
    double truth = phongLike(wo, wi), got = t.lookup(wo, wi)[0];
    double rel = std::abs(got - truth) / truth;
    sumSq += rel * rel;
    worst = std::max(worst, rel);
  }
  double rms = std::sqrt(sumSq / n);
  std::printf("phong-like: rms relative error %.4f, worst %.4f\n", rms, worst);
  EXPECT_LT(rms, 0.06);
  EXPECT_LT(worst, 0.4);
}

// Largest ratio between the values at neighbouring queries of a sweep.
double worstStepRatio(const std::vector<double>& v) {
  double worst = 1;
  for (size_t i = 1; i < v.size(); ++i) {
    double lo = std::min(v[i - 1], v[i]), hi = std::max(v[i - 1], v[i]);
    worst = std::max(worst, lo > 0 ? hi / lo : (hi > 0 ? kInfinity : 1.0));
  }
  return worst;
}

// Sweeps at 0.5 degree steps through the specular peak: wi across the plane of incidence
// (theta from -80 to 80 degrees on the mirror side) and around the normal (phi 0 to 360 at the
// mirror's theta), for wo at 10..70 degrees.
std::vector<std::vector<double>> sweeps(const IrregularBrdfTable& t) {
  std::vector<std::vector<double>> out;
  for (double thetaO : {10.0, 30.0, 50.0, 70.0}) {
    Vector3f wo = fromDegrees(thetaO, 0);
    std::vector<double> across, around;
    for (double th = -80; th <= 80; th += 0.5)
      across.push_back(t.lookup(wo, fromDegrees(std::abs(th), th < 0 ? 0 : 180))[0]);
    for (double ph = 0; ph <= 360; ph += 0.5)
      around.push_back(t.lookup(wo, fromDegrees(thetaO, ph))[0]);
    out.push_back(across);
    out.push_back(around);
  }
  return out;
}

// An isolated spike (or pit): a value more than twice (or under half) both neighbours.
int isolatedSpikes(const std::vector<double>& v) {
  int n = 0;
  for (size_t i = 1; i + 1 < v.size(); ++i)
    n += (v[i] > 2 * v[i - 1] && v[i] > 2 * v[i + 1]) ||
         (2 * v[i] < v[i - 1] && 2 * v[i] < v[i + 1]);
  return n;
}

TEST(IrregularBrdfLookup, NearbyQueriesGiveNearbyValues) {
  // The book's estimate is smooth except where the doubling radius changes: there a ring of
  // samples enters or leaves with weights exp(-100 d^2) comparable to the inner ones, and the
  // value steps by as much as those samples differ from the inner ones. On smooth data that is
  // the lobe's variation across the ring (measured: at most 1.58x); never an isolated spike.
  IrregularBrdfTable t = sampledTable(4000, 5, phongLike);
  double worst = 1;
  int spikes = 0;
  for (const auto& s : sweeps(t)) {
    worst = std::max(worst, worstStepRatio(s));
    spikes += isolatedSpikes(s);
  }
  std::printf("phong-like: worst ratio between queries 0.5 degrees apart %.4f\n", worst);
  EXPECT_EQ(spikes, 0);
  EXPECT_LT(worst, 2);
}

TEST(IrregularBrdfLookup, ReciprocalAndTwoSided) {
  IrregularBrdfTable t = sampledTable(1000, 7, phongLike);
  RNG rng(8);
  for (int i = 0; i < 2000; ++i) {
    Vector3f wo = randomDirection(rng), wi = randomDirection(rng);
    Spectrum f = t.lookup(wo, wi);
    ASSERT_EQ(f, t.lookup(wi, wo));
    ASSERT_EQ(f, t.lookup(otherHemisphere(wo), otherHemisphere(wi)));
    ASSERT_TRUE(t.lookup(wo, otherHemisphere(wi)).isBlack());
  }
}

TEST(IrregularBrdfLookup, RadiusStopsWhereTheBookLoopStops) {
  // Samples placed at chosen distances from the query: theta_i = theta_o = 45 degrees, so only
  // the azimuth difference (the second coordinate, dphi / pi) differs from the query's 90 degrees.
  auto at = [](double d2, Float value) {
    double dphi = 90 + 180 * std::sqrt(d2);
    return IrregularBrdfSample{fromDegrees(45, 0), fromDegrees(45, dphi), Spectrum(value)};
  };
  Vector3f wo = fromDegrees(45, 0), wi = fromDegrees(45, 90);
  auto weight = [](double d2) { return std::exp(-100 * d2); };
  {
    // Three inside 0.001: the first radius suffices; the sample at 0.0015 is left out.
    IrregularBrdfTable t({at(0.0002, 1), at(0.0005, 2), at(0.0009, 3), at(0.0015, 100)});
    IrregularBrdfEstimate e = t.estimate(wo, wi);
    EXPECT_EQ(e.found, 3);
    EXPECT_FLOAT_EQ(e.radius2, 0.001f);
    double expect = (weight(0.0002) + 2 * weight(0.0005) + 3 * weight(0.0009)) /
                    (weight(0.0002) + weight(0.0005) + weight(0.0009));
    EXPECT_NEAR(e.value[0], expect, 1e-3);
  }
  {
    // The third sample is at 0.003: 0.001 and 0.002 hold too few, 0.004 holds four.
    IrregularBrdfTable t(
        {at(0.0002, 1), at(0.0025, 1), at(0.003, 1), at(0.0035, 1), at(0.0045, 100)});
    IrregularBrdfEstimate e = t.estimate(wo, wi);
    EXPECT_EQ(e.found, 4);
    EXPECT_FLOAT_EQ(e.radius2, 0.004f);
    EXPECT_NEAR(e.value[0], 1, 1e-6);
  }
  {
    // Two samples in all: the radius grows until it exceeds 1.5 (0.001 * 2^11) and their mean
    // is returned, not 0.
    IrregularBrdfTable t({at(0.01, 2), at(0.2, 4)});
    IrregularBrdfEstimate e = t.estimate(wo, wi);
    EXPECT_EQ(e.found, 2);
    EXPECT_FLOAT_EQ(e.radius2, 2.048f);
    EXPECT_NEAR(e.value[0], (2 * weight(0.01) + 4 * weight(0.2)) / (weight(0.01) + weight(0.2)),
                1e-5);
  }
  {
    // One sample farther than the last radius from the query (grazing pair with dphi = pi
    // against a pair at the normal, 3 apart squared): nothing found, f = 0.
    IrregularBrdfTable t({{fromDegrees(89.9, 0), fromDegrees(89.9, 180), Spectrum(1)}});
    IrregularBrdfEstimate e = t.estimate(Vector3f(0, 0, 1), Vector3f(0, 0, 1));
    EXPECT_EQ(e.found, 0);
    EXPECT_FLOAT_EQ(e.radius2, 2.048f);
    EXPECT_TRUE(e.value.isBlack());
  }
}

TEST(IrregularBrdfLookup, AgreesWithTheBookLoopAndIsZeroOnlyWhereItFindsNothing) {
  // Dense data (the doubling stops early) and sparse data (it runs to the end, sometimes
  // finding nothing): the kd-tree shortcut stops at the same radius with the same samples.
  for (int n : {2000, 40, 2}) {
    IrregularBrdfTable t = sampledTable(n, 9 + n, phongLike);
    RNG rng(10);
    int zeros = 0;
    for (int i = 0; i < 500; ++i) {
      Vector3f wo = randomDirection(rng), wi = randomDirection(rng);
      IrregularBrdfEstimate fast = t.estimate(wo, wi), book = bookLoop(t, wo, wi);
      ASSERT_EQ(fast.found, book.found) << n;
      ASSERT_EQ(fast.radius2, book.radius2) << n;
      // The sums run in another order: rounding only.
      EXPECT_NEAR(fast.value[0], book.value[0], 1e-5 * book.value[0]) << n;
      EXPECT_EQ(fast.value.isBlack(), book.found == 0) << n;
      zeros += book.found == 0;
    }
    if (n == 2000) {
      EXPECT_EQ(zeros, 0);
    }
  }
}

}  // namespace
}  // namespace candela
