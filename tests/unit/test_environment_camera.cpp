// The environment camera: raster (x, y) <-> (theta = pi y / yres, phi = 2 pi x / xres) with
// pbrt-v2's axes (y up), unit directions, origin and clipping spheres, differentials, factory.
#include <gtest/gtest.h>

#include <cmath>

#include "cameras/camera.h"
#include "cameras/environment_camera.h"
#include "core/rng.h"
#include "support/geometry_expect.h"
#include "support/param_items.h"

namespace candela {
namespace {

std::unique_ptr<Camera> makeEnv(const ParamSet& ps, const Transform& worldToCamera, Point2i res) {
  return createCamera("environment", ps, inverse(worldToCamera), res, FileLoc{"e.pbrt", 1, 1});
}

TEST(EnvironmentCamera, PixelToSphericalCoordinatesClosedForm) {
  const int w = 360, h = 180;
  auto cam = makeEnv(ParamSet(), Transform(), {w, h});
  RNG rng(3);
  for (int i = 0; i < 2000; ++i) {
    Float x = rng.uniformFloat() * w, y = rng.uniformFloat() * h;
    Ray r;
    ASSERT_EQ(cam->generateRay(test::cameraSample(x, y), &r), 1.f);
    ASSERT_NEAR(r.d.length(), 1, 1e-6);
    // Back from the direction: theta from +y, phi from +x towards +z.
    double theta = std::acos(std::clamp(double(r.d.y), -1.0, 1.0));
    double phi = std::atan2(double(r.d.z), double(r.d.x));
    if (phi < 0) phi += 2 * M_PI;
    ASSERT_NEAR(theta, M_PI * y / h, 1e-3) << x << " " << y;
    // phi is undefined at the poles; elsewhere it is 2 pi x / w (mod 2 pi).
    if (std::sin(theta) > 1e-2) {
      double expected = 2 * M_PI * x / w, diff = std::remainder(phi - expected, 2 * M_PI);
      ASSERT_NEAR(diff, 0, 1e-3 / std::sin(theta)) << x << " " << y;
    }
  }
}

TEST(EnvironmentCamera, AxesFollowPbrtV2) {
  const int w = 400, h = 200;
  auto cam = makeEnv(ParamSet(), Transform(), {w, h});
  struct Case {
    Point2f raster;
    Vector3f dir;
  };
  for (Case c : {Case{{0, 0}, {0, 1, 0}},                           // top row: up
                 Case{{200, 200}, {0, -1, 0}},                      // bottom row: down
                 Case{{0, 100}, {1, 0, 0}},                         // left edge, horizon: +x
                 Case{{100, 100}, {0, 0, 1}},                       // a quarter across: +z
                 Case{{200, 100}, {-1, 0, 0}},                      // centre: -x
                 Case{{300, 100}, {0, 0, -1}},                      // three quarters: -z
                 Case{{50, 50}, {0.5f, std::sqrt(0.5f), 0.5f}}}) {  // theta = phi = pi/4
    Ray r;
    cam->generateRay(test::cameraSample(c.raster.x, c.raster.y), &r);
    test::expectNear(r.d, c.dir, 1e-6f);
  }
}

TEST(EnvironmentCamera, OriginClippingSpheresAndCameraTransform) {
  ParamSet ps;
  ps.add(test::floats("hither", {0.5f}));
  ps.add(test::floats("yon", {10}));
  ps.add(test::floats("shutteropen", {2}));
  ps.add(test::floats("shutterclose", {4}));
  Point3f eye(1, -2, 3);
  // Camera looking along world +x with +z up: camera +y (the top row) is world +z.
  Transform w2c = lookAt(eye, eye + Vector3f(1, 0, 0), Vector3f(0, 0, 1));
  auto cam = makeEnv(ps, w2c, {64, 32});
  CameraSample s = test::cameraSample(20, 0);
  s.time = 0.5f;
  Ray r;
  cam->generateRay(s, &r);
  test::expectNear(r.d, Vector3f(0, 0, 1), 1e-6f);
  EXPECT_FLOAT_EQ(r.time, 3);
  // Rays start on the hither sphere and end on the yon sphere around the camera's position.
  for (Point2f p : {Point2f(5, 7), Point2f(40, 30), Point2f(63, 16)}) {
    cam->generateRay(test::cameraSample(p.x, p.y), &r);
    EXPECT_NEAR(distance(r.o, eye), 0.5f, 1e-5);
    EXPECT_NEAR(distance(r(r.tMax), eye), 10, 1e-4);
    // The origin lies along the ray's own direction from the eye.
    test::expectNear(normalize(r.o - eye), r.d, 1e-5f);
  }
  // A scaling cameraToWorld scales the clipping radii with it; directions stay unit length.
  auto scaled = makeEnv(ps, scale(0.5f, 0.5f, 0.5f), {64, 32});
  scaled->generateRay(test::cameraSample(10, 10), &r);
  EXPECT_NEAR(r.d.length(), 1, 1e-6);
  EXPECT_NEAR(distance(r.o, Point3f(0, 0, 0)), 1, 1e-5);
}

TEST(EnvironmentCamera, DifferentialsAreTheNeighbouringPixelsDirections) {
  auto cam = makeEnv(ParamSet(), Transform(), {100, 50});
  CameraSample s = test::cameraSample(30.5f, 20.25f);
  RayDifferential rd;
  cam->generateRayDifferential(s, &rd);
  ASSERT_TRUE(rd.hasDifferentials);
  Ray rx, ry;
  cam->generateRay(test::cameraSample(31.5f, 20.25f), &rx);
  cam->generateRay(test::cameraSample(30.5f, 21.25f), &ry);
  test::expectNear(rd.rxDirection, rx.d, 1e-6f);
  test::expectNear(rd.ryDirection, ry.d, 1e-6f);
  // One pixel down is pi/50 of latitude.
  EXPECT_NEAR(std::acos(dot(rd.d, rd.ryDirection)), M_PI / 50, 1e-4);
}

// The renderer lets the sampler pass over the lens dimensions for this camera: its rays must not
// depend on them.
TEST(EnvironmentCamera, ReadsNoLensSample) {
  auto cam =
      makeEnv(ParamSet(), lookAt(Point3f(1, 2, 3), Point3f(0, 0, 0), Vector3f(0, 1, 0)), {100, 50});
  EXPECT_FALSE(cam->readsLensSample());
  EXPECT_TRUE(test::rayIgnoresLensSample(*cam, 30.5f, 20.25f));
}

}  // namespace
}  // namespace candela
