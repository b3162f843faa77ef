// The sphere: analytic hits, partial spheres, differential geometry, orientation, area and the
// sampling routines' densities.
#include <gtest/gtest.h>

#include "core/rng.h"
#include "core/sampling.h"
#include "shapes/sphere.h"
#include "support/geometry_expect.h"
#include "support/param_items.h"
#include "support/random_geometry.h"
#include "support/shape_sample_expect.h"

namespace candela {
namespace {

TEST(SphereShape, HitThroughCentre) {
  SphereShape s(Transform(), false, 1, -1, 1, 360);
  Ray ray(Point3f(0, 0, -5), Vector3f(0, 0, 1));
  Float t;
  SurfaceInteraction isect;
  ASSERT_TRUE(s.intersect(ray, &t, &isect));
  EXPECT_NEAR(t, 4, 1e-6);
  test::expectNear(Vector3f(isect.p), Vector3f(0, 0, -1), 1e-5f);
  test::expectNear(Vector3f(isect.n), Vector3f(0, 0, -1), 1e-4f);
  // The same for a translated sphere and oblique rays: t = |o - c| - r.
  Transform o2w = translate(Vector3f(3, -2, 7));
  SphereShape moved(o2w, false, 2.5f, -2.5f, 2.5f, 360);
  RNG rng(1);
  for (int i = 0; i < 100; ++i) {
    Vector3f d = test::randomDirection(rng);
    Point3f c(3, -2, 7);
    Ray r(c - d * 11, d);
    ASSERT_TRUE(moved.intersect(r, &t, nullptr));
    EXPECT_NEAR(t, 11 - 2.5f, 1e-4f);
  }
}

TEST(SphereShape, Miss) {
  SphereShape s(Transform(), false, 1, -1, 1, 360);
  Float t;
  EXPECT_FALSE(s.intersect(Ray(Point3f(0, 1.01f, -5), Vector3f(0, 0, 1)), &t, nullptr));
  EXPECT_FALSE(s.intersectP(Ray(Point3f(0, 0, -5), Vector3f(0, 0, -1))));       // behind
  EXPECT_FALSE(s.intersectP(Ray(Point3f(0, 0, -5), Vector3f(0, 0, 1), 3.9f)));  // short
  EXPECT_TRUE(s.intersectP(Ray(Point3f(0, 0, -5), Vector3f(0, 0, 1), 4.1f)));
}

TEST(SphereShape, HitFromInside) {
  SphereShape s(Transform(), false, 2, -2, 2, 360);
  RNG rng(2);
  for (int i = 0; i < 100; ++i) {
    Vector3f d = test::randomDirection(rng);
    Float t;
    SurfaceInteraction isect;
    ASSERT_TRUE(s.intersect(Ray(Point3f(0, 0, 0), d * 3), &t, &isect));
    EXPECT_NEAR(t, 2.f / 3, 1e-5f);
    // Outward normal: along the ray, facing away from the inside.
    EXPECT_GT(dot(isect.n, d), 0.999f);
  }
}

TEST(SphereShape, PartialSphereClipsAndUsesFarRoot) {
  // zmax = 0.5: a ray down the axis misses the cut-off cap and hits the inside of the bottom.
  SphereShape cut(Transform(), false, 1, -1, 0.5f, 360);
  Float t;
  SurfaceInteraction isect;
  ASSERT_TRUE(cut.intersect(Ray(Point3f(0.01f, 0, 5), Vector3f(0, 0, -1)), &t, &isect));
  EXPECT_NEAR(t, 6, 1e-3);
  EXPECT_LT(isect.p.z, -0.99f);
  // phimax = 90: only x >= 0, y >= 0. The near root at phi ~ 150 degrees is clipped.
  SphereShape wedge(Transform(), false, 1, -1, 1, 90);
  Ray r(Point3f(-5, 0.5f, 0.1f), Vector3f(1, 0, 0));
  ASSERT_TRUE(wedge.intersect(r, &t, &isect));
  EXPECT_NEAR(isect.p.x, std::sqrt(1 - 0.25f - 0.01f), 1e-5);
  EXPECT_NEAR(isect.uv.x, std::atan2(0.5f, isect.p.x) / kPiOver2, 1e-5);
  // Both roots clipped: miss.
  EXPECT_FALSE(wedge.intersectP(Ray(Point3f(-5, -0.5f, 0.1f), Vector3f(1, 0, 0))));
  // A band: z in [-0.2, 0.2] cannot be hit along the axis.
  SphereShape band(Transform(), false, 1, -0.2f, 0.2f, 360);
  EXPECT_FALSE(band.intersectP(Ray(Point3f(0, 0, 5), Vector3f(0, 0, -1))));
  EXPECT_TRUE(band.intersectP(Ray(Point3f(0, 0, 0), Vector3f(1, 0, 0))));
}

TEST(SphereShape, DifferentialGeometry) {
  const Float r = 2;
  SphereShape s(Transform(), false, r, -r, r, 360);
  RNG rng(3);
  int hits = 0;
  for (int i = 0; i < 500; ++i) {
    Point3f o = Point3f(test::randomDirection(rng) * 6);
    Vector3f d = Vector3f(test::randomDirection(rng) * 1.5f) - Vector3f(o);
    Float t;
    SurfaceInteraction isect;
    if (!s.intersect(Ray(o, d), &t, &isect)) continue;
    ++hits;
    Vector3f p(isect.p);
    EXPECT_NEAR(p.length(), r, 1e-5f);
    test::expectNear(Vector3f(isect.n), p / r, 1e-4f);
    // Tangents lie in the tangent plane; for a sphere dn/du = dp/du / r (Weingarten).
    EXPECT_NEAR(dot(isect.dpdu, isect.n), 0, 1e-4f * isect.dpdu.length());
    EXPECT_NEAR(dot(isect.dpdv, isect.n), 0, 1e-4f * isect.dpdv.length());
    test::expectNear(Vector3f(isect.dndu), isect.dpdu / r, 1e-3f * isect.dpdu.length());
    test::expectNear(Vector3f(isect.dndv), isect.dpdv / r, 1e-3f * isect.dpdv.length());
    // (u, v): phi / 2 pi and theta from the bottom.
    Float phi = std::atan2(p.y, p.x);
    if (phi < 0) phi += 2 * kPi;
    EXPECT_NEAR(isect.uv.x, phi / (2 * kPi), 1e-4f);
    EXPECT_NEAR(isect.uv.y, (std::acos(p.z / r) - kPi) / -kPi, 1e-4f);
    // The bound covers p.
    EXPECT_GE(isect.pError.x, 0);
    EXPECT_TRUE(s.worldBound().inside(isect.p));
  }
  EXPECT_GT(hits, 100);
}

TEST(SphereShape, PoleIsFinite) {
  SphereShape s(Transform(), false, 1, -1, 1, 360);
  Float t;
  SurfaceInteraction isect;
  ASSERT_TRUE(s.intersect(Ray(Point3f(0, 0, 3), Vector3f(0, 0, -1)), &t, &isect));
  EXPECT_FALSE(isect.dpdu.hasNaN());
  EXPECT_FALSE(isect.dpdv.hasNaN());
  EXPECT_FALSE(isect.dndu.hasNaN());
  EXPECT_FALSE(isect.n.hasNaN());
  EXPECT_GT(isect.dpdu.lengthSquared(), 0);
  EXPECT_NEAR(isect.n.z, 1, 1e-4f);
}

TEST(SphereShape, Area) {
  EXPECT_NEAR(SphereShape(Transform(), false, 2, -2, 2, 360).area(), 16 * kPi, 1e-4);
  // phiMax r (zMax - zMin).
  EXPECT_NEAR(SphereShape(Transform(), false, 2, -1, 0.5f, 90).area(), kPiOver2 * 2 * 1.5f, 1e-4);
  // A uniform scale by 3 multiplies the area by 9; zmin/zmax are clamped to the radius.
  EXPECT_NEAR(SphereShape(scale(3, 3, 3), false, 1, -5, 5, 360).area(), 36 * kPi, 1e-3);
}

TEST(SphereShape, ReverseOrientationFlipsNormal) {
  SphereShape s(Transform(), true, 1, -1, 1, 360);
  Float t;
  SurfaceInteraction isect;
  ASSERT_TRUE(s.intersect(Ray(Point3f(0, 0, -5), Vector3f(0, 0, 1)), &t, &isect));
  test::expectNear(Vector3f(isect.n), Vector3f(0, 0, 1), 1e-4f);  // inward
  Float pdf;
  Interaction it = s.sample(Point2f(0.3f, 0.6f), &pdf);
  EXPECT_LT(dot(it.n, Vector3f(it.p)), 0);
}

TEST(SphereShape, HandednessSwapFlipsNormal) {
  // Under a mirror, dp/du x dp/dv turns inward; the xor with the handedness swap flips it back so
  // that the normal stays outward, as the object-space normal transformed as a normal does.
  Transform mirror = scale(-1, 1, 1);
  ASSERT_TRUE(mirror.swapsHandedness());
  for (bool reverse : {false, true}) {
    SphereShape s(mirror, reverse, 1, -1, 1, 360);
    RNG rng(4);
    for (int i = 0; i < 50; ++i) {
      Vector3f d = test::randomDirection(rng);
      Float t;
      SurfaceInteraction isect;
      ASSERT_TRUE(s.intersect(Ray(Point3f(d * -4), d), &t, &isect));
      Vector3f out = normalize(Vector3f(isect.p));
      EXPECT_NEAR(dot(isect.n, out), reverse ? -1 : 1, 1e-4f);
      Vector3f crossN = normalize(cross(isect.dpdu, isect.dpdv));
      EXPECT_NEAR(dot(isect.n, crossN), reverse ? 1 : -1, 1e-4f);
    }
    Float pdf;
    Interaction it = s.sample(Point2f(0.7f, 0.2f), &pdf);
    EXPECT_NEAR(dot(it.n, normalize(Vector3f(it.p))), reverse ? -1 : 1, 1e-4f);
  }
}

// Shape::sampleFrom (the default, here over the sphere's cone sampling): sample(ref, ...) and the
// direction normalize(p - ref.p), bit for bit.
TEST(SphereShape, SampleFromGivesSampleAndItsDirection) {
  SphereShape s(Transform(), false, 1, -1, 1, 360);
  RNG rng(8);
  int compared = 0;
  for (int i = 0; i < 1000; ++i) {
    Float r = 2 + 3 * rng.uniformFloat();
    Vector3f dir = sampleUniformSphere(Point2f(rng.uniformFloat(), rng.uniformFloat()));
    Interaction ref(Point3f(0, 0, 0) + dir * r, 0);
    if (test::expectSampleFromIsSample(s, ref, Point2f(rng.uniformFloat(), rng.uniformFloat())))
      ++compared;
  }
  EXPECT_GT(compared, 990);
}

TEST(SphereShape, AreaSamplingPartialSphere) {
  SphereShape s(rotateX(30), false, 2, -0.5f, 1.5f, 200);
  Transform w2o = inverse(rotateX(30));
  RNG rng(5);
  Float phiMax = radians(200);
  for (int i = 0; i < 1000; ++i) {
    Float pdf;
    Float u0 = rng.uniformFloat();
    Interaction it = s.sample(Point2f(u0, rng.uniformFloat()), &pdf);
    EXPECT_NEAR(pdf, 1 / s.area(), 1e-6f);
    Point3f q = w2o(it.p);
    EXPECT_NEAR(Vector3f(q).length(), 2, 1e-5f);
    EXPECT_GE(q.z, -0.5f - 1e-5f);
    EXPECT_LE(q.z, 1.5f + 1e-5f);
    Float phi = std::atan2(q.y, q.x);
    if (phi < 0) phi += 2 * kPi;
    EXPECT_LE(phi, phiMax + 1e-4f);
    // The error bound covers the point; the normal is outward.
    EXPECT_GT(dot(it.n, it.p - Point3f(0, 0, 0)), 0);
  }
}

// Integrates pdf(ref, wi) over all directions by importance sampling a cone of directions
// around axis (cosMax = -1: the whole sphere), with a fixed seed.
Float integratePdf(const Shape& s, const Interaction& ref, const Vector3f& axis, Float cosMax,
                   int n) {
  Vector3f x, y;
  coordinateSystem(axis, &x, &y);
  RNG rng(6);
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    Float u0 = rng.uniformFloat();
    Vector3f l = sampleUniformCone(Point2f(u0, rng.uniformFloat()), cosMax);
    Vector3f wi = x * l.x + y * l.y + axis * l.z;
    sum += s.pdf(ref, wi) / uniformConePdf(cosMax);
  }
  return Float(sum / n);
}

TEST(SphereShape, ConePdfIntegratesToOne) {
  Transform o2w = translate(Vector3f(1, 2, 3)) * rotateZ(40) * scale(1.5f, 1.5f, 1.5f);
  SphereShape s(o2w, false, 1, -1, 1, 360);
  Point3f c(1, 2, 3);
  // Near: the whole sphere of directions (the cone covers ~12%).
  Interaction near(c + Vector3f(0, 0, -2.25f), 0);
  EXPECT_NEAR(integratePdf(s, near, Vector3f(0, 0, 1), -1, 1000000), 1, 0.01);
  // Far: a tiny cone (half-angle ~0.086 degrees), sampled within a cone 1.5 times as wide.
  Vector3f toC = normalize(Vector3f(1, 1, 1));
  Interaction far(c - toC * 1000, 0);
  Float sinMax = 1.5f / 1000, cosOuter = std::sqrt(1 - 2.25f * sinMax * sinMax);
  EXPECT_NEAR(integratePdf(s, far, toC, cosOuter, 200000), 1, 0.01);
}

TEST(SphereShape, InsidePdfIntegratesToOne) {
  SphereShape s(Transform(), false, 1, -1, 1, 360);
  Interaction inside(Point3f(0.3f, -0.2f, 0.1f), 0);
  EXPECT_NEAR(integratePdf(s, inside, Vector3f(0, 0, 1), -1, 200000), 1, 0.01);
}

TEST(SphereShape, ConeSamplesLieOnTheVisibleSphere) {
  Transform o2w = translate(Vector3f(-4, 1, 2)) * scale(0.5f, 0.5f, 0.5f);
  SphereShape s(o2w, false, 2, -2, 2, 360);
  Point3f c(-4, 1, 2);
  RNG rng(7);
  for (Float dist : {1.2f, 3.f, 50.f, 5000.f}) {
    Interaction ref(c + normalize(Vector3f(0.3f, -1, 0.4f)) * dist, 0);
    for (int i = 0; i < 2000; ++i) {
      Float pdf;
      Float u0 = rng.uniformFloat();
      Interaction it = s.sample(ref, Point2f(u0, rng.uniformFloat()), &pdf);
      EXPECT_NEAR(distance(it.p, c), 1, 1e-5f * std::max(Float(1), dist / 100));
      EXPECT_GE(pdf, 0);
      Vector3f wi = it.p - ref.p;
      EXPECT_NEAR(s.pdf(ref, wi), pdf, 1e-3f * pdf);
      // On the side facing ref: the ray toward it hits the sphere there first.
      EXPECT_GE(dot(it.n, -wi), -1e-3f * wi.length());
      Float t;
      SurfaceInteraction isect;
      if (!s.intersect(Ray(ref.p, wi * 1.001f), &t, &isect)) {
        ADD_FAILURE() << "no hit toward sample " << it.p << " from " << ref.p;
        continue;
      }
      EXPECT_NEAR(distance(isect.p, it.p), 0, 2e-3f * std::max(Float(1), dist / 100));
    }
  }
}

TEST(SphereShape, RejectsBadRays) {
  SphereShape s(Transform(), false, 1, -1, 1, 360);
  Float nan = std::numeric_limits<Float>::quiet_NaN();
  Float t;
  EXPECT_FALSE(s.intersect(Ray(Point3f(nan, 0, -5), Vector3f(0, 0, 1)), &t, nullptr));
  EXPECT_FALSE(s.intersect(Ray(Point3f(0, 0, -5), Vector3f(0, nan, 1)), &t, nullptr));
  EXPECT_FALSE(s.intersect(Ray(Point3f(0, 0, -5), Vector3f(0, 0, 0)), &t, nullptr));
  EXPECT_FALSE(s.intersect(Ray(Point3f(0, 0, -kInfinity), Vector3f(0, 0, 1)), &t, nullptr));
  EXPECT_FALSE(s.intersect(Ray(Point3f(0, 0, -5), Vector3f(0, 0, 1), nan), &t, nullptr));
}

TEST(SphereShape, Factory) {
  ParamSet ps;
  ps.add(test::floats("radius", {2}));
  ps.add(test::floats("zmax", {1}));
  ps.add(test::floats("phimax", {180}));
  std::unique_ptr<Shape> s = createSphereShape(Transform(), false, ps);
  EXPECT_STREQ(s->kind(), "sphere");
  EXPECT_NEAR(s->area(), kPi * 2 * 3, 1e-4);
  ps.forEachUnused([](const ParamItem& item) { ADD_FAILURE() << item.name << " unused"; });

  ParamSet bad;
  bad.add(test::floats("radius", {-1}, FileLoc{"scene.pbrt", 7, 3}));
  try {
    createSphereShape(Transform(), false, bad);
    FAIL() << "expected a SceneError";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.location().line, 7);
    EXPECT_NE(std::string(e.what()).find("radius"), std::string::npos);
  }
  // A NaN zmin would make a sphere nothing ever hits, silently.
  ParamSet nanZ;
  nanZ.add(
      test::floats("zmin", {std::numeric_limits<Float>::quiet_NaN()}, FileLoc{"s.pbrt", 9, 1}));
  try {
    createSphereShape(Transform(), false, nanZ);
    FAIL() << "expected a SceneError";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.location().line, 9);
    EXPECT_NE(std::string(e.what()).find("zmin"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace candela
