// Vectors, bounds, rays: the closed forms of the lrt draft ch. 2.
#include <gtest/gtest.h>

#include "core/bounds.h"
#include "core/ray.h"
#include "core/rng.h"

namespace candela {
namespace {

TEST(Vector, DotCrossAndLength) {
  Vector3f a(1, 2, 3), b(-4, 5, 0.5f);
  EXPECT_FLOAT_EQ(dot(a, b), -4 + 10 + 1.5f);
  Vector3f c = cross(a, b);
  EXPECT_NEAR(dot(c, a), 0, 1e-5);
  EXPECT_NEAR(dot(c, b), 0, 1e-5);
  EXPECT_FLOAT_EQ(Vector3f(3, 4, 0).length(), 5);
  EXPECT_FLOAT_EQ(normalize(Vector3f(0, 0, -7)).z, -1);
  // Left-handed: x cross y = z as in pbrt.
  EXPECT_EQ(cross(Vector3f(1, 0, 0), Vector3f(0, 1, 0)), Vector3f(0, 0, 1));
}

TEST(Vector, CoordinateSystemIsOrthonormal) {
  RNG rng(3);
  for (int i = 0; i < 1000; ++i) {
    Vector3f v = normalize(
        Vector3f(rng.uniformFloat() - 0.5f, rng.uniformFloat() - 0.5f, rng.uniformFloat() - 0.5f));
    Vector3f s, t;
    coordinateSystem(v, &s, &t);
    EXPECT_NEAR(s.length(), 1, 1e-5);
    EXPECT_NEAR(t.length(), 1, 1e-5);
    EXPECT_NEAR(dot(s, v), 0, 1e-5);
    EXPECT_NEAR(dot(t, v), 0, 1e-5);
    EXPECT_NEAR(dot(s, t), 0, 1e-5);
  }
  Vector3f s, t;
  coordinateSystem(Vector3f(0, 0, -1), &s, &t);  // the branch point of the construction
  EXPECT_NEAR(dot(s, t), 0, 1e-6);
  EXPECT_NEAR(s.length(), 1, 1e-6);
}

TEST(Bounds, DefaultIsEmptyAndUnionGrows) {
  Bounds3f b;
  EXPECT_TRUE(b.empty());
  b = unionOf(b, Point3f(1, 2, 3));
  EXPECT_FALSE(b.empty());
  EXPECT_EQ(b.pMin, Point3f(1, 2, 3));
  b = unionOf(b, Point3f(-1, 6, 0));
  EXPECT_EQ(b.pMin, Point3f(-1, 2, 0));
  EXPECT_EQ(b.pMax, Point3f(1, 6, 3));
  EXPECT_TRUE(b.inside(Point3f(0, 3, 1)));
  EXPECT_FALSE(b.inside(Point3f(0, 7, 1)));
  EXPECT_FLOAT_EQ(b.surfaceArea(), 2 * (2 * 4 + 2 * 3 + 4 * 3));
  EXPECT_EQ(b.maximumExtent(), 1);
  Bounds3f u = unionOf(b, Bounds3f(Point3f(10, 10, 10), Point3f(11, 11, 11)));
  EXPECT_EQ(u.pMax, Point3f(11, 11, 11));
}

TEST(Bounds2i, IntersectionAndArea) {
  Bounds2i a(Point2i(0, 0), Point2i(10, 5)), b(Point2i(5, -2), Point2i(20, 3));
  Bounds2i c = intersect(a, b);
  EXPECT_EQ(c, Bounds2i(Point2i(5, 0), Point2i(10, 3)));
  EXPECT_EQ(c.area(), 15);
  EXPECT_TRUE(intersect(a, Bounds2i(Point2i(11, 0), Point2i(12, 1))).empty());
}

TEST(Ray, OffsetOriginMovesToTheRequestedSide) {
  Point3f p(1, 1, 1);
  Vector3f err(1e-3f, 1e-3f, 1e-3f);
  Normal3f n(0, 0, 1);
  Point3f above = offsetRayOrigin(p, err, n, Vector3f(0, 0, 1));
  Point3f below = offsetRayOrigin(p, err, n, Vector3f(0.3f, 0, -1));
  EXPECT_GT(above.z, p.z + 1e-3f * 0.999f);
  EXPECT_LT(below.z, p.z - 1e-3f * 0.999f);
  EXPECT_EQ(above.x, p.x);
}

TEST(Numeric, NextFloatUpDown) {
  EXPECT_GT(nextFloatUp(1.f), 1.f);
  EXPECT_LT(nextFloatDown(1.f), 1.f);
  EXPECT_GT(nextFloatUp(-0.f), 0.f);
  EXPECT_LT(nextFloatDown(0.f), 0.f);
  EXPECT_EQ(nextFloatUp(kInfinity), kInfinity);
  EXPECT_GT(gamma(3), 3 * kMachineEpsilon);
}

TEST(Rng, PermutationElementIsAPermutation) {
  for (uint32_t n : {1u, 2u, 3u, 7u, 16u, 100u, 1000u}) {
    std::vector<int> seen(n, 0);
    for (uint32_t i = 0; i < n; ++i) {
      uint32_t e = permutationElement(i, n, 12345 + n);
      ASSERT_LT(e, n);
      ++seen[e];
    }
    for (uint32_t i = 0; i < n; ++i) EXPECT_EQ(seen[i], 1) << "n=" << n << " i=" << i;
  }
  // Different seeds give different permutations.
  int same = 0;
  for (uint32_t i = 0; i < 64; ++i)
    same += permutationElement(i, 64, 1) == permutationElement(i, 64, 2);
  EXPECT_LT(same, 16);
}

TEST(Rng, UniformFloatInUnitInterval) {
  RNG rng(42);
  double sum = 0;
  for (int i = 0; i < 100000; ++i) {
    Float u = rng.uniformFloat();
    ASSERT_GE(u, 0.f);
    ASSERT_LT(u, 1.f);
    sum += u;
  }
  EXPECT_NEAR(sum / 100000, 0.5, 0.005);  // ~5.5 standard errors
}

}  // namespace
}  // namespace candela
