// The watertight triangle test's t > 0 error bound is scale-invariant: a triangle and a ray
// scaled together (the direction not normalised, so t stays 1) give the same answer at every
// scale. pbrt 3e's bound mixes scaled and unscaled z and rejected such hits on small triangles.
#include <gtest/gtest.h>

#include "core/rng.h"
#include "shapes/triangle_mesh.h"

namespace candela {
namespace {

TEST(TriangleScale, HitsAtEveryScaleWithUnnormalisedRays) {
  RNG rng(81);
  for (Float s : {1e-8f, 1e-6f, 1e-4f, 1e-2f, 1.f, 1e2f, 1e4f, 1e6f}) {
    TriangleMesh mesh(scale(s, s, s), false, {0, 1, 2}, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    TriangleShape tri(&mesh, 0);
    int misses = 0;
    for (int i = 0; i < 1000; ++i) {
      Float a = rng.uniformFloat(), b = rng.uniformFloat();
      if (a + b > 0.98f || a < 0.01f || b < 0.01f) continue;
      Point3f target(a * s, b * s, 0);
      // From 0.1 to 100 triangle sizes away, at any angle above the plane: t = 1 at the target.
      Float dist = s * std::pow(10.f, 3 * rng.uniformFloat() - 1);
      Point3f o = target + Vector3f(rng.uniformFloat() - 0.5f, rng.uniformFloat() - 0.5f, 1) * dist;
      Float t;
      if (!tri.intersect(Ray(o, target - o), &t, nullptr)) ++misses;
    }
    EXPECT_EQ(misses, 0) << "scale " << s;
  }
}

}  // namespace
}  // namespace candela
