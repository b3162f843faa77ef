// Degenerate triangles (zero area, repeated vertices, NaN or infinite vertices) never report a
// hit and never break the Embree build; rays with NaN or infinite components, a zero direction
// or a NaN tMax miss every shape kind without crashing.
#include <gtest/gtest.h>

#include "accel/embree/embree_aggregate.h"
#include "core/rng.h"
#include "core/sampling.h"
#include "shape_zoo.h"
#include "support/test_device.h"

namespace candela {
namespace {

TEST(DegenerateTriangles, NeverHitAndNeverBreakTheBuild) {
  const Float nan = std::numeric_limits<Float>::quiet_NaN();
  // Triangle 0 is a proper one, far to the side (so the build has something real); the others:
  // collinear points, a repeated vertex index, coincident positions, a NaN and an infinite
  // vertex. All lie around the origin, where the rays go.
  std::vector<Point3f> p = {{10, 10, 0},        {11, 10, 0},       {10, 11, 0},  // proper
                            {-1, -1, 0},        {0, 0, 0},         {1, 1, 0},    // collinear
                            {-1, 0, 0.5f},      {1, 0, 0.5f},                    // repeated index
                            {0.3f, 0.3f, 0.2f},                                  // coincident
                            {-1, 1, 0},         {nan, 0, 0},       {1, -1, 0},   // NaN
                            {-1, 0, 1},         {kInfinity, 0, 1}, {1, 1, 1}};   // infinite
  std::vector<int> indices = {0, 1, 2, 3, 4, 5, 6, 7, 7, 8, 8, 8, 9, 10, 11, 12, 13, 14};
  test::ShapeScene scene;
  scene.add(std::make_unique<TriangleMesh>(Transform(), false, indices, p));
  ASSERT_EQ(scene.shapes.size(), 6u);
  EmbreeAggregate agg(test::embreeDevice(), scene.primitives);  // must not throw
  RNG rng(71);
  int properHits = 0;
  for (int i = 0; i < 100000; ++i) {
    Float u0 = rng.uniformFloat(), u1 = rng.uniformFloat();
    Vector3f d = sampleUniformSphere(Point2f(u0, u1));
    // Through the degenerate triangles' points and lines, from all around; every 8th ray at the
    // proper triangle as a control.
    Point3f target = i % 8 == 0 ? Point3f(10.3f, 10.3f, 0)
                                : p[3 + size_t(rng.uniformFloat() * 12) % 12] * rng.uniformFloat();
    if (target.hasNaN() || !std::isfinite(target.x)) target = Point3f(0, 0, 0);
    Ray ray(target - d * 5, d);
    SurfaceInteraction si;
    if (agg.intersect(ray, &si)) {
      EXPECT_EQ(si.primitive, &scene.primitives[0]) << "ray toward " << target;
      ++properHits;
    }
    for (size_t k = 1; k < scene.shapes.size(); ++k) {
      Float t;
      EXPECT_FALSE(scene.shapes[k]->intersect(ray, &t, nullptr)) << k;
      EXPECT_FALSE(scene.shapes[k]->intersectP(ray)) << k;
    }
    if (i % 8 != 0) {
      EXPECT_FALSE(agg.intersectP(ray)) << "ray toward " << target;
    }
  }
  EXPECT_GT(properHits, 10000);
}

TEST(BadRays, MissEveryShapeKind) {
  const Float nan = std::numeric_limits<Float>::quiet_NaN(), inf = kInfinity;
  std::vector<Ray> rays = {Ray(Point3f(nan, 0, -5), Vector3f(0, 0, 1)),
                           Ray(Point3f(0, nan, -5), Vector3f(0, 0, 1)),
                           Ray(Point3f(0, 0, -5), Vector3f(nan, 0, 1)),
                           Ray(Point3f(0, 0, -5), Vector3f(0, 0, nan)),
                           Ray(Point3f(-inf, 0, 0), Vector3f(1, 0, 0)),
                           Ray(Point3f(0, 0, inf), Vector3f(0, 0, -1)),
                           Ray(Point3f(0, 0, -5), Vector3f(inf, 0, 1)),
                           Ray(Point3f(0, 0, -5), Vector3f(0, -inf, 1)),
                           Ray(Point3f(0, 0, -5), Vector3f(0, 0, 0)),
                           Ray(Point3f(0, 0, -5), Vector3f(0, 0, 1), nan),
                           Ray(Point3f(0, 0, -5), Vector3f(0, 0, 1), -1),
                           Ray(Point3f(nan, nan, nan), Vector3f(nan, nan, nan))};
  for (const test::Placement& place : test::placements()) {
    for (auto& scene : test::shapeZoo(place.t)) {
      EmbreeAggregate agg(test::embreeDevice(), scene->primitives);
      for (const Ray& r : rays) {
        SurfaceInteraction si;
        EXPECT_FALSE(agg.intersect(r, &si)) << scene->name << " " << place.name;
        EXPECT_FALSE(agg.intersectP(r)) << scene->name << " " << place.name;
        for (const auto& s : scene->shapes) {
          Float t;
          EXPECT_FALSE(s->intersect(r, &t, nullptr)) << scene->name;
          EXPECT_FALSE(s->intersectP(r)) << scene->name;
        }
      }
    }
  }
}

}  // namespace
}  // namespace candela
