// The orthographic camera: every ray along camera +z, raster <-> screen window mapping, thin-lens
// focus on the plane z = focaldistance with the lens centred on the film point, clipping planes,
// differentials, factory.
#include <gtest/gtest.h>

#include <cmath>

#include "cameras/camera.h"
#include "cameras/orthographic_camera.h"
#include "support/geometry_expect.h"
#include "support/param_items.h"

namespace candela {
namespace {

std::unique_ptr<Camera> makeOrtho(const ParamSet& ps, const Transform& worldToCamera, Point2i res) {
  return createCamera("orthographic", ps, inverse(worldToCamera), res, FileLoc{"o.pbrt", 1, 1});
}

TEST(OrthographicCamera, EveryRayRunsAlongTheViewDirection) {
  Point3f eye(1, 2, 3), look(4, -1, 5);
  Transform w2c = lookAt(eye, look, Vector3f(0, 1, 0));
  auto cam = makeOrtho(ParamSet(), w2c, {64, 48});
  Vector3f view = normalize(look - eye);
  for (Point2f p : {Point2f(0, 0), Point2f(32, 24), Point2f(63.5f, 1.25f), Point2f(7, 47.9f)}) {
    Ray r;
    EXPECT_EQ(cam->generateRay(test::cameraSample(p.x, p.y), &r), 1.f);
    test::expectNear(r.d, view, 1e-6f);
    EXPECT_NEAR(r.d.length(), 1, 1e-6);
    // In camera space the direction is exactly +z.
    test::expectNear(w2c(r.d), Vector3f(0, 0, 1), 1e-6f);
  }
}

TEST(OrthographicCamera, RasterMapsOntoTheScreenWindow) {
  // Default window for a 200 x 100 image: [-2, 2] x [-1, 1]; raster (0, 0) is its top-left
  // corner (xmin, ymax), raster (xres, yres) the bottom-right (xmax, ymin). The ray leaves from
  // the screen point (on the hither plane, z = 0 by default).
  auto cam = makeOrtho(ParamSet(), Transform(), {200, 100});
  struct Case {
    Point2f raster;
    Point2f screen;
  };
  for (Case c : {Case{{0, 0}, {-2, 1}}, Case{{200, 100}, {2, -1}}, Case{{100, 50}, {0, 0}},
                 Case{{150, 25}, {1, 0.5f}}, Case{{12.5f, 80}, {-1.75f, -0.6f}}}) {
    Ray r;
    cam->generateRay(test::cameraSample(c.raster.x, c.raster.y), &r);
    test::expectNear(r.o, Point3f(c.screen.x, c.screen.y, 0), 1e-6f);
    auto& ortho = dynamic_cast<OrthographicCamera&>(*cam);
    Point2f s = ortho.rasterToScreen(c.raster);
    EXPECT_NEAR(s.x, c.screen.x, 1e-6);
    EXPECT_NEAR(s.y, c.screen.y, 1e-6);
  }
  // An explicit window, portrait image: the window maps onto the image whatever its aspect.
  ParamSet ps;
  ps.add(test::floats("screenwindow", {-3, 5, 10, 12}));
  cam = makeOrtho(ps, Transform(), {40, 80});
  Ray r;
  cam->generateRay(test::cameraSample(10, 60),
                   &r);  // x: -3 + 8 * 10/40 = -1; y: 12 - 2 * 60/80 = 10.5
  test::expectNear(r.o, Point3f(-1, 10.5f, 0), 1e-5f);
}

TEST(OrthographicCamera, ClippingPlanesAndShutter) {
  ParamSet ps;
  ps.add(test::floats("hither", {2}));
  ps.add(test::floats("yon", {9}));
  ps.add(test::floats("shutteropen", {0.5f}));
  ps.add(test::floats("shutterclose", {1.5f}));
  Transform w2c = scale(2, 2, 2) * translate(Vector3f(1, 0, 0));
  auto cam = makeOrtho(ps, w2c, {10, 10});
  CameraSample s = test::cameraSample(3, 4);
  s.time = 0.75f;
  Ray r;
  cam->generateRay(s, &r);
  EXPECT_FLOAT_EQ(r.time, 1.25f);
  EXPECT_NEAR(r.d.length(), 1, 1e-6);
  EXPECT_NEAR(w2c(r.o).z, 2, 1e-5);
  EXPECT_NEAR(w2c(r(r.tMax)).z, 9, 1e-4);
}

TEST(OrthographicCamera, PointsOnTheFocalPlaneStaySharp) {
  // Every lens position's ray through a film point meets the pinhole ray on z = focaldistance,
  // at the film point's screen position; the lens is centred on the film point, so the origins
  // lie within lensradius of it (pbrt-v2/v3 centre it on the axis instead).
  const Float focal = 6, lens = 0.4f;
  ParamSet ps;
  ps.add(test::floats("lensradius", {lens}));
  ps.add(test::floats("focaldistance", {focal}));
  auto cam = makeOrtho(ps, Transform(), {80, 80});
  auto& ortho = dynamic_cast<OrthographicCamera&>(*cam);
  for (Point2f film : {Point2f(40, 40), Point2f(2.5f, 70), Point2f(79, 3)}) {
    Point2f screen = ortho.rasterToScreen(film);
    Float spread = 0;
    for (Point2f u : {Point2f(0.1f, 0.2f), Point2f(0.9f, 0.5f), Point2f(0.3f, 0.95f),
                      Point2f(0.01f, 0.01f), Point2f(0.5f, 0.5f)}) {
      Ray r;
      cam->generateRay(test::cameraSample(film.x, film.y, u), &r);
      EXPECT_NEAR(r.d.length(), 1, 1e-6);
      Point3f p = r((focal - r.o.z) / r.d.z);
      test::expectNear(p, Point3f(screen.x, screen.y, focal), 2e-5f);
      Float offAxis = std::hypot(r.o.x - screen.x, r.o.y - screen.y);
      EXPECT_LE(offAxis, lens + 1e-3f);
      spread = std::max(spread, offAxis);
    }
    EXPECT_GT(spread, 0.2f);  // the rays really start across the lens
  }
  // Off the focal plane, a point is blurred: rays through different lens points miss each other.
  Ray a, b;
  cam->generateRay(test::cameraSample(40, 40, Point2f(0.1f, 0.5f)), &a);
  cam->generateRay(test::cameraSample(40, 40, Point2f(0.9f, 0.5f)), &b);
  Float z = 2 * focal;
  EXPECT_GT(distance(a((z - a.o.z) / a.d.z), b((z - b.o.z) / b.d.z)), 0.3f);
}

TEST(OrthographicCamera, AnalyticDifferentialsMatchFiniteDifferences) {
  for (Float lens : {0.f, 0.3f}) {
    ParamSet ps;
    ps.add(test::floats("lensradius", {lens}));
    ps.add(test::floats("focaldistance", {4}));
    auto cam =
        makeOrtho(ps, lookAt(Point3f(0, 1, -3), Point3f(0.5f, 0, 0), Vector3f(0, 1, 0)), {160, 90});
    CameraSample s = test::cameraSample(31.25f, 70.5f, Point2f(0.8f, 0.35f));
    RayDifferential analytic, generic;
    cam->generateRayDifferential(s, &analytic);
    cam->Camera::generateRayDifferential(s, &generic);
    ASSERT_TRUE(analytic.hasDifferentials);
    test::expectNear(analytic.o, generic.o, 1e-6f);
    test::expectNear(analytic.d, generic.d, 1e-6f);
    test::expectNear(analytic.rxOrigin, generic.rxOrigin, 1e-5f);
    test::expectNear(analytic.ryOrigin, generic.ryOrigin, 1e-5f);
    test::expectNear(analytic.rxDirection, generic.rxDirection, 1e-5f);
    test::expectNear(analytic.ryDirection, generic.ryDirection, 1e-5f);
    if (lens == 0) {
      // A pinhole orthographic camera's offset rays are parallel, one pixel (2/90) apart.
      test::expectNear(analytic.rxDirection, analytic.d, 1e-6f);
      EXPECT_NEAR(distance(analytic.rxOrigin, analytic.o), 2.f / 90, 1e-5);
      EXPECT_NEAR(distance(analytic.ryOrigin, analytic.o), 2.f / 90, 1e-5);
    }
  }
}

TEST(OrthographicCamera, FactoryErrors) {
  ParamSet sw;
  sw.add(test::floats("screenwindow", {1, 1, 0, 2}));
  EXPECT_THROW(makeOrtho(sw, Transform(), {10, 10}), SceneError);
  ParamSet clip;
  clip.add(test::floats("hither", {5}));
  clip.add(test::floats("yon", {1}));
  EXPECT_THROW(makeOrtho(clip, Transform(), {10, 10}), SceneError);
  ParamSet lens;
  lens.add(test::floats("lensradius", {-1}));
  EXPECT_THROW(makeOrtho(lens, Transform(), {10, 10}), SceneError);
}

}  // namespace
}  // namespace candela
