// --hyperboloid-normal: the exact normal is the fitted surface's; pbrt's (the p1-p2 segment's
// direction turned by phi as dp/dv, pbrt 3e §3.5.3) equals it where the segment is a ruling and
// leans off the surface elsewhere, by an angle that the segment's distance from a ruling sets.
#include <gtest/gtest.h>

#include <cmath>

#include "shapes/hyperboloid.h"

namespace candela {
namespace {

HyperboloidShape make(const Point3f& p1, const Point3f& p2, HyperboloidNormal normal) {
  return HyperboloidShape(Transform(), false, p1, p2, 360, normal);
}

// The hit of a horizontal ray at height z coming in along the direction (cos a, sin a).
SurfaceInteraction hitAt(const Shape& s, double z, double a) {
  Point3f o(Float(10 * std::cos(a)), Float(10 * std::sin(a)), Float(z));
  Float t;
  SurfaceInteraction si;
  EXPECT_TRUE(s.intersect(Ray(o, Vector3f(-o.x, -o.y, 0)), &t, &si));
  return si;
}

// The fitted surface x^2 + y^2 = d + k z^2 has the outward gradient (x, y, -k z).
Vector3f surfaceNormal(const HyperboloidShape& s, const Point3f& p) {
  return normalize(Vector3f(p.x, p.y, Float(-s.fit().k * p.z)));
}

double angleBetween(const Vector3f& a, const Vector3f& b) {
  return std::acos(std::clamp(double(dot(normalize(a), normalize(b))), -1.0, 1.0));
}

TEST(HyperboloidNormal, BothAreTheSurfacesOnARuling) {
  // (1, 0, -1)-(0, 1, 1) is a ruling of x^2 + y^2 - z^2 / 2 = 1/2.
  Point3f p1(1, 0, -1), p2(0, 1, 1);
  HyperboloidShape exact = make(p1, p2, HyperboloidNormal::Exact);
  HyperboloidShape pbrt = make(p1, p2, HyperboloidNormal::SegmentAsPbrt);
  for (double z : {-0.8, -0.3, 0.0, 0.4, 0.9})
    for (double a : {0.2, 1.9, 4.0}) {
      SurfaceInteraction e = hitAt(exact, z, a), p = hitAt(pbrt, z, a);
      EXPECT_LT(angleBetween(Vector3f(e.n), surfaceNormal(exact, e.p)), 1e-5) << z << " " << a;
      EXPECT_LT(angleBetween(Vector3f(p.n), Vector3f(e.n)), 1e-5) << z << " " << a;
      EXPECT_EQ(e.uv, p.uv);
    }
}

TEST(HyperboloidNormal, PbrtsLeansOffTheSurfaceWhereTheSegmentIsNoRuling) {
  // The conformance scenes' segment: pbrt fits a surface through p2 that misses p1.
  Point3f p1(0.8f, 0, -0.8f), p2(0.3f, 0.5f, 0.8f);
  HyperboloidShape exact = make(p1, p2, HyperboloidNormal::Exact);
  HyperboloidShape pbrt = make(p1, p2, HyperboloidNormal::SegmentAsPbrt);
  double largest = 0;
  for (double z : {-0.7, -0.3, 0.0, 0.4, 0.7})
    for (double a : {0.2, 1.9, 4.0}) {
      SurfaceInteraction e = hitAt(exact, z, a), p = hitAt(pbrt, z, a);
      // The same point and (u, v): only the normal differs.
      EXPECT_LT(distance(e.p, p.p), 1e-6f);
      EXPECT_EQ(e.uv, p.uv);
      EXPECT_LT(angleBetween(Vector3f(e.n), surfaceNormal(exact, e.p)), 1e-5) << z << " " << a;
      // pbrt's: perpendicular to dp/du and to the segment's direction turned by phi.
      double phi = 2 * std::numbers::pi * double(p.uv[0]);
      Vector3f seg(Float((p2.x - p1.x) * std::cos(phi) - (p2.y - p1.y) * std::sin(phi)),
                   Float((p2.x - p1.x) * std::sin(phi) + (p2.y - p1.y) * std::cos(phi)),
                   p2.z - p1.z);
      EXPECT_NEAR(dot(normalize(Vector3f(p.n)), normalize(seg)), 0, 1e-5);
      EXPECT_NEAR(dot(normalize(Vector3f(p.n)), normalize(p.dpdu)), 0, 1e-5);
      // Still on the outward side.
      EXPECT_GT(dot(Vector3f(p.n), Vector3f(e.n)), 0);
      largest = std::max(largest, angleBetween(Vector3f(p.n), Vector3f(e.n)));
    }
  // Leaning by several degrees: enough to darken a matte surface under a sky by 0.3-1.5%
  // (docs/pbrt-differences.md).
  EXPECT_GT(largest, 0.05);
}

}  // namespace
}  // namespace candela
