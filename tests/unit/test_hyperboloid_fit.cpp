// The hyperboloid as pbrt-v2/v3 define it (pbrt 2e/3e §3.5.3): the quadric x^2 + y^2 = d + k z^2
// through p2 and 2 p2 - p1, its narrowest section at z = 0 whatever the segment's own; p1 on it
// only when the segment is a ruling; v from the (swapped, when p2.z = 0) p1; the profile's spans
// (ellipsoid, two sheets), exact area against a numerical integral, samples on the surface.
#include <gtest/gtest.h>

#include "core/rng.h"
#include "quadric_models.h"

namespace candela {
namespace {

using test::D3;

HyperboloidShape make(const D3& p1, const D3& p2, Float phiMaxDeg = 360) {
  return HyperboloidShape(Transform(), false, Point3f(Float(p1[0]), Float(p1[1]), Float(p1[2])),
                          Point3f(Float(p2[0]), Float(p2[1]), Float(p2[2])), phiMaxDeg);
}

// The distance from the axis at which a horizontal ray at height z, coming in from far along the
// direction (cos a, sin a), first meets the shape; -1 if it misses.
double radiusAt(const Shape& s, double z, double a = 0.3) {
  Point3f o(Float(10 * std::cos(a)), Float(10 * std::sin(a)), Float(z));
  Float t;
  SurfaceInteraction si;
  if (!s.intersect(Ray(o, Vector3f(-o.x, -o.y, 0)), &t, &si)) return -1;
  return std::hypot(double(si.p.x), double(si.p.y));
}

// The area of the surface of revolution of the model's profile rho(z) (its radius at u = 0)
// between heights z0 and z1 over phiMax: frusta on n segments, then Richardson's step from n to
// 2n (the frusta's error is O(1/n^2)). Independent of the shape's closed form.
double revolvedArea(const test::QuadricModel& m, double z1Param, double dzParam, double z0,
                    double z1, double phiMax, int n) {
  auto frusta = [&](int k) {
    double sum = 0, zPrev = z0;
    auto rho = [&](double z) {
      D3 p = m.P(0, (z - z1Param) / dzParam);
      return std::hypot(p[0], p[1]);
    };
    double rPrev = rho(z0);
    for (int i = 1; i <= k; ++i) {
      double z = z0 + (z1 - z0) * i / k, r = rho(z);
      sum += 0.5 * (r + rPrev) * std::hypot(r - rPrev, z - zPrev);
      zPrev = z;
      rPrev = r;
    }
    return phiMax * sum;
  };
  double a = frusta(n), b = frusta(2 * n);
  return b + (b - a) / 3;
}

TEST(HyperboloidFit, PassesThroughP2AndTheReflectedP1) {
  const std::vector<std::pair<D3, D3>> pairs = {{{0.8, 0, -0.8}, {0.3, 0.5, 0.8}},
                                                {{1, 0.3, -0.8}, {-0.2, 1.1, 0.9}},
                                                {{0.4, 0.9, 0.7}, {1, 0, -0.6}},
                                                {{1.2, 0.2, -0.2}, {0.9, 0.3, 0.3}}};
  for (const auto& [p1, p2] : pairs) {
    double a[3] = {p1[0], p1[1], p1[2]}, b[3] = {p2[0], p2[1], p2[2]};
    HyperboloidFit f = fitHyperboloid(a, b);
    ASSERT_FALSE(f.degenerate);
    D3 q = {2 * p2[0] - p1[0], 2 * p2[1] - p1[1], 2 * p2[2] - p1[2]};
    for (const D3& p : {p2, q}) {
      double rho2 = p[0] * p[0] + p[1] * p[1];
      EXPECT_NEAR(f.d + f.k * p[2] * p[2], rho2, 1e-12 * (1 + rho2));
    }
    // And the shape is where the fit says: a ray at p2's height meets it at p2's radius.
    HyperboloidShape s = make(p1, p2);
    EXPECT_NEAR(radiusAt(s, p2[2]), std::hypot(p2[0], p2[1]), 1e-5);
  }
}

TEST(HyperboloidFit, NarrowestAtZeroNotWhereTheSegmentIs) {
  // hyperboloid-uv's shape: the segment is narrowest at z = 0.48, but the fitted surface is
  // symmetric about z = 0 (p1.z = -p2.z), so at p1's height its radius is p2's (sqrt 0.34), not
  // p1's (0.8): the "cooling tower" pbrt-v3 draws, not the sweep of the segment.
  HyperboloidShape s = make({0.8, 0, -0.8}, {0.3, 0.5, 0.8});
  double r2 = std::hypot(0.3, 0.5);
  EXPECT_NEAR(radiusAt(s, 0.8), r2, 1e-5);
  EXPECT_NEAR(radiusAt(s, -0.8), r2, 1e-5);
  double waist = radiusAt(s, 0);
  for (double z : {-0.6, -0.3, -0.1, 0.1, 0.3, 0.6}) {
    EXPECT_GT(radiusAt(s, z), waist) << z;
    EXPECT_NEAR(radiusAt(s, z), radiusAt(s, -z), 1e-5) << z;
  }
  // The segment's own point at z = 0, (0.55, 0.25), is farther out: not on the surface.
  EXPECT_LT(waist, std::hypot(0.55, 0.25) - 0.05);
}

TEST(HyperboloidFit, ARulingKeepsP1OnTheSurface) {
  // (1, 0, -1)-(0, 1, 1) is a ruling of x^2 + y^2 - z^2 / 2 = 1/2: every point of it is on the
  // surface, p1 included, and u = 0 along it.
  HyperboloidShape s = make({1, 0, -1}, {0, 1, 1});
  for (double v : {0.0, 0.25, 0.5, 0.9}) {
    double x = 1 - v, y = v, z = -1 + 2 * v;
    EXPECT_NEAR(radiusAt(s, z, std::atan2(y, x)), std::hypot(x, y), 1e-5) << v;
  }
}

TEST(HyperboloidFit, P2AtZeroHeightSwapsTheEnds) {
  // pbrt swaps p1 and p2 when p2.z = 0 (its fit divides by p2.z), and v then runs from the
  // statement's p2: at z = 0.25, v = 0.25, not 0.75. The normal still points away from the axis.
  HyperboloidShape s = make({0.5, 0.5, 1}, {1, 0, 0});
  Float t;
  SurfaceInteraction si;
  ASSERT_TRUE(s.intersect(Ray(Point3f(5, 0.2f, 0.25f), Vector3f(-1, 0, 0)), &t, &si));
  EXPECT_NEAR(si.uv.y, 0.25f, 1e-6);
  EXPECT_GT(si.n.x, 0);
  EXPECT_EQ(s.fit().p1[2], 0);
}

TEST(HyperboloidFit, DegenerateFitHasNoSurface) {
  // p1.z = 3 p2.z: 2 p2 - p1 is at -p2.z, so the "quadric" is the planes z = +-p2.z.
  HyperboloidShape s = make({1, 0, 3}, {0.5, 0, 1});
  EXPECT_TRUE(s.fit().degenerate);
  EXPECT_EQ(s.area(), 0);
  EXPECT_FALSE(s.intersectP(Ray(Point3f(5, 0, 2), Vector3f(-1, 0, 0))));
}

TEST(HyperboloidFit, LineThroughTheOriginSweepsItsCone) {
  // pbrt-v3 never finishes its fit here (the default p1 = 0, p2 = (1, 1, 1) among such lines);
  // the limit of the fits is the cone the segment sweeps.
  HyperboloidShape s = make({0, 0, 0}, {1, 1, 1});
  EXPECT_EQ(s.fit().d, 0);
  EXPECT_NEAR(s.fit().k, 2, 1e-12);
  EXPECT_NEAR(radiusAt(s, 0.5), std::sqrt(0.5), 1e-5);
}

struct PartialCase {
  const char* name;
  D3 p1, p2;
  double phiMaxDeg;
  double zLo, zHi;  // where the surface is, from the fit's closed form
  double zGap;      // a height in [zMin, zMax] without surface
};

// Fits whose surface covers only part of [zMin, zMax]: a hyperboloid of two sheets (k = 5/4,
// d = -1: nothing below sqrt(0.8)) and an ellipsoid (nothing below its bottom).
std::vector<PartialCase> partialCases() {
  std::vector<PartialCase> cases;
  cases.push_back({"two sheets", {1, 0, 0}, {-0.5, 0, 1}, 300, std::sqrt(0.8), 1, 0.4});
  PartialCase e{"ellipsoid", {1.3, 0, -1}, {0.8, 0.1, -0.2}, 360, 0, -0.2, 0};
  double a[3] = {e.p1[0], e.p1[1], e.p1[2]}, b[3] = {e.p2[0], e.p2[1], e.p2[2]};
  HyperboloidFit f = fitHyperboloid(a, b);
  e.zLo = -std::sqrt(f.d / -f.k);
  e.zGap = 0.5 * (e.zLo - 1);
  cases.push_back(e);
  return cases;
}

TEST(HyperboloidFit, PartialSpansAreaAndSamples) {
  for (const PartialCase& c : partialCases()) {
    double k, d;
    test::hyperboloidModelFit(c.p1, c.p2, &k, &d);
    ASSERT_LT(c.zHi - c.zLo, std::abs(c.p2[2] - c.p1[2]) - 0.05) << c.name;  // really partial
    test::QuadricModel m = test::hyperboloidModel(c.p1, c.p2, c.phiMaxDeg);
    HyperboloidShape s = make(c.p1, c.p2, Float(c.phiMaxDeg));
    double phiMax = test::toRad(c.phiMaxDeg);
    double expected = revolvedArea(m, c.p1[2], c.p2[2] - c.p1[2], c.zLo, c.zHi, phiMax, 20000);
    EXPECT_NEAR(s.area(), expected, 2e-6 * expected) << c.name;
    // Samples lie on the fitted surface, inside the part that exists.
    RNG rng(5);
    for (int i = 0; i < 2000; ++i) {
      Float pdf;
      Interaction it = s.sample(Point2f(rng.uniformFloat(), rng.uniformFloat()), &pdf);
      double x = it.p.x, y = it.p.y, z = it.p.z;
      EXPECT_NEAR(x * x + y * y, d + k * z * z, 1e-5) << c.name;
      EXPECT_GE(z, c.zLo - 1e-6) << c.name;
      EXPECT_LE(z, c.zHi + 1e-6) << c.name;
      EXPECT_NEAR(pdf, 1 / s.area(), 1e-6 / s.area());
    }
    // No hit where the surface does not exist.
    EXPECT_LT(radiusAt(s, c.zGap), 0) << c.name;
  }
}

}  // namespace
}  // namespace candela
