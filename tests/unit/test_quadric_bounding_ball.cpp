// The quadrics' bounding-ball rejection (a float test before the double-precision root search):
// it must never turn a hit into a miss. Rays are aimed at points just behind each shape's
// surface, from near and far, at angles down to a grazing 0.6 degrees, under transforms far from
// the origin, tiny, huge, mirrored and non-uniformly scaled; every one must be reported hit. The
// reference is the geometry itself, not the shape's code: each of these surfaces bounds a convex
// solid, so a ray aimed at a point just across it, near the point, crosses it near the point.
#include <gtest/gtest.h>

#include "core/rng.h"
#include "quadric_models.h"
#include "support/random_geometry.h"

namespace candela {
namespace {

struct Placement {
  const char* name;
  Transform t;
};

std::vector<Placement> placements() {
  return {{"identity", Transform()},
          {"far", translate(Vector3f(1e4f, -3e3f, 2e4f))},
          {"tiny", translate(Vector3f(0.1f, 0.2f, 0.3f)) * scale(1e-3f, 1e-3f, 1e-3f)},
          {"huge", scale(1e3f, 1e3f, 1e3f)},
          {"stretched", rotate(37, Vector3f(1, 2, 3)) * scale(1, 3, 0.2f)},
          {"mirrored", translate(Vector3f(-5, 4, 1)) * scale(-2, 2, 2)}};
}

TEST(QuadricBoundingBall, NeverRejectsARayAimedAtTheSurface) {
  RNG rng(7);
  for (const test::QuadricModel& m : test::allModels()) {
    // A hyperboloid of one sheet bounds no convex solid: a ray aimed just behind it may pass
    // between its sheets' curves without crossing, so the premise below does not hold for it.
    if (m.name.find("hyperboloid") != std::string::npos) continue;
    for (const Placement& place : placements()) {
      std::unique_ptr<Quadric> shape = m.make(place.t, false);
      Float size = Float(m.size) * maxComponent(abs(place.t(Vector3f(1, 1, 1))));
      // The crossing must stay well inside the sampled part of the surface, whose margin is set
      // by the transform's smallest stretch.
      Float window = Float(0.02 * m.size) * std::min({place.t(Vector3f(1, 0, 0)).length(),
                                                      place.t(Vector3f(0, 1, 0)).length(),
                                                      place.t(Vector3f(0, 0, 1)).length()});
      int misses = 0, rays = 0;
      for (int i = 0; i < 400; ++i) {
        // A point away from the shape's edges, moved behind the surface by more than its
        // rounding, so that a ray aimed at it from the front crosses the surface first.
        Float pdf;
        Interaction target = shape->sample(
            Point2f(0.1f + 0.8f * rng.uniformFloat(), 0.1f + 0.8f * rng.uniformFloat()), &pdf);
        Vector3f n = normalize(Vector3f(target.n)), s, t;
        Float depth = Float(1e-4) * size + 4 * maxComponent(target.pError);
        Point3f aim = target.p - n * depth;
        // From the front, at angles to the normal down to grazing (cosine 0.01) where the
        // crossing stays within the window of the point.
        coordinateSystem(n, &s, &t);
        Float cosMin = std::max(Float(0.01), depth / window);
        if (cosMin >= 1) continue;
        Float cosTheta = cosMin + (1 - cosMin) * rng.uniformFloat();
        Float sinTheta = std::sqrt(1 - cosTheta * cosTheta), phi = 2 * kPi * rng.uniformFloat();
        Vector3f back =
            s * (sinTheta * std::cos(phi)) + t * (sinTheta * std::sin(phi)) + n * cosTheta;
        // From 1e-2 to 1e4 sizes away, but not nearer than 1e4 of the point's rounding errors (a
        // root there is where the ray may start, not a hit), and not so far that the origin's
        // own rounding (a float step at its largest coordinate) moves the ray by a quarter of the
        // depth: then it may pass in front of the surface.
        Float nearest = std::max(Float(1e-2) * size, Float(1e4) * maxComponent(target.pError));
        Float farthest = std::min(Float(1e4) * size, Float(0.25) * depth * Float(0x1p23) -
                                                         maxComponent(abs(Vector3f(aim))));
        if (!(farthest > nearest)) continue;
        Float distance = nearest * std::pow(farthest / nearest, rng.uniformFloat());
        Point3f origin = aim + back * distance;
        ++rays;
        if (!shape->intersectP(Ray(origin, aim - origin, 1 + Float(1e-3)))) ++misses;
      }
      EXPECT_GT(rays, 300) << m.name << ", " << place.name;
      EXPECT_EQ(misses, 0) << m.name << ", " << place.name << ": " << misses << " of " << rays
                           << " rays aimed at the surface missed it";
    }
  }
}

// And it does reject: rays that pass a sphere by a tenth of its radius, or stop short of it, are
// misses (these take the early exit; the test above shows the exit is never wrongly taken).
TEST(QuadricBoundingBall, RaysThatPassBySphereMiss) {
  SphereShape sphere(translate(Vector3f(1e5f, 0, 0)), false, 2, -2, 2, 360);
  RNG rng(8);
  for (int i = 0; i < 200; ++i) {
    Vector3f d = test::randomDirection(rng), s, t;
    coordinateSystem(d, &s, &t);
    Point3f centre(1e5f, 0, 0);
    Point3f origin = centre + s * Float(2.2) - d * 50;
    EXPECT_FALSE(sphere.intersectP(Ray(origin, d)));
    EXPECT_FALSE(sphere.intersectP(Ray(centre - d * 50, d, 47)));  // stops short
    EXPECT_TRUE(sphere.intersectP(Ray(centre - d * 50, d, 49)));
  }
}

}  // namespace
}  // namespace candela
