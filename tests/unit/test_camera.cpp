// The perspective camera: view direction, field of view along the shorter axis, image
// orientation, LookAt, thin-lens focus, clipping planes, shutter, differentials, factory.
#include <gtest/gtest.h>

#include <cmath>

#include "cameras/camera.h"
#include "cameras/perspective_camera.h"
#include "support/geometry_expect.h"
#include "support/param_items.h"

namespace candela {
namespace {

Float angleBetween(const Vector3f& a, const Vector3f& b) {
  return std::acos(clamp(dot(normalize(a), normalize(b)), -1, 1));
}

std::unique_ptr<Camera> makeCamera(const ParamSet& ps, const Transform& worldToCamera,
                                   Point2i res) {
  return createCamera("perspective", ps, inverse(worldToCamera), res, FileLoc{"c.pbrt", 1, 1});
}

TEST(PerspectiveCamera, CentreRayAlongViewDirection) {
  Point3f eye(1, 2, 3), look(4, -1, 5);
  ParamSet ps;
  ps.add(test::floats("fov", {50}));
  auto cam = makeCamera(ps, lookAt(eye, look, Vector3f(0, 1, 0)), {200, 100});
  Ray r;
  EXPECT_EQ(cam->generateRay(test::cameraSample(100, 50), &r), 1.f);
  test::expectNear(r.d, normalize(look - eye), 1e-6f);
  EXPECT_NEAR(r.d.length(), 1, 1e-6);
  // The origin is the eye: without a "hither" the ray is not clipped (pbrt-v2/v3; the lrt draft's
  // absolute 1e-3 clipped whole scenes of that size).
  test::expectNear(r.o, eye, 1e-6f);
}

TEST(PerspectiveCamera, FovSpansTheShorterAxis) {
  const Float fov = 60;
  ParamSet ps;
  ps.add(test::floats("fov", {fov}));
  Transform identity;
  // Landscape: the fov is vertical; the horizontal half-angle is atan(aspect tan(fov/2)).
  auto wide = makeCamera(ps, identity, {300, 100});
  Ray top, bottom, left;
  wide->generateRay(test::cameraSample(150, 0), &top);
  wide->generateRay(test::cameraSample(150, 100), &bottom);
  wide->generateRay(test::cameraSample(0, 50), &left);
  Vector3f view(0, 0, 1);
  EXPECT_NEAR(degrees(angleBetween(top.d, view)), fov / 2, 1e-3);
  EXPECT_NEAR(degrees(angleBetween(bottom.d, view)), fov / 2, 1e-3);
  EXPECT_NEAR(angleBetween(left.d, view), std::atan(3 * std::tan(radians(fov / 2))), 1e-5);
  // Portrait: the fov is horizontal.
  auto tall = makeCamera(ps, identity, {100, 300});
  Ray l, t;
  tall->generateRay(test::cameraSample(0, 150), &l);
  tall->generateRay(test::cameraSample(50, 0), &t);
  EXPECT_NEAR(degrees(angleBetween(l.d, view)), fov / 2, 1e-3);
  EXPECT_NEAR(angleBetween(t.d, view), std::atan(3 * std::tan(radians(fov / 2))), 1e-5);
}

TEST(PerspectiveCamera, PointAtHalfFovProjectsToTheImageEdge) {
  // The other way round: a world point fov/2 above the axis lands on the top edge (y = 0).
  const Float fov = 40;
  ParamSet ps;
  ps.add(test::floats("fov", {fov}));
  auto cam = makeCamera(ps, Transform(), {400, 300});
  Float h = std::tan(radians(fov / 2));
  Point3f target(0, 10 * h, 10);
  Ray r;
  cam->generateRay(test::cameraSample(200, 0), &r);
  Float t = (target.z - r.o.z) / r.d.z;
  test::expectNear(r(t), target, 1e-4f);
}

TEST(PerspectiveCamera, RasterXRightAndYDown) {
  // Camera at the origin looking down +z with +y up: camera space is world space (left-handed,
  // pbrt): raster x increasing is +x, raster y increasing is -y.
  auto cam = makeCamera(ParamSet(), lookAt(Point3f(0, 0, 0), Point3f(0, 0, 1), Vector3f(0, 1, 0)),
                        {64, 64});
  Ray right, down;
  cam->generateRay(test::cameraSample(60, 32), &right);
  cam->generateRay(test::cameraSample(32, 60), &down);
  EXPECT_GT(right.d.x, 0.1f);
  EXPECT_NEAR(right.d.y, 0, 1e-6);
  EXPECT_LT(down.d.y, -0.1f);
  EXPECT_NEAR(down.d.x, 0, 1e-6);
  // A general LookAt: looking along +x with +z up, image right is cross(up, view) = +y.
  auto cam2 = makeCamera(ParamSet(), lookAt(Point3f(1, 2, 3), Point3f(4, 2, 3), Vector3f(0, 0, 1)),
                         {64, 64});
  cam2->generateRay(test::cameraSample(60, 32), &right);
  cam2->generateRay(test::cameraSample(32, 60), &down);
  EXPECT_GT(right.d.y, 0.1f);
  EXPECT_LT(down.d.z, -0.1f);
}

TEST(PerspectiveCamera, LookAtMapsLookDirectionToPlusZ) {
  Point3f eye(-2, 5, 1), look(3, 0, 7);
  Transform w2c = lookAt(eye, look, Vector3f(0.2f, 1, 0));
  test::expectNear(w2c(normalize(look - eye)), Vector3f(0, 0, 1), 1e-6f);
  Point3f p = w2c(look);
  EXPECT_NEAR(p.x, 0, 1e-5);
  EXPECT_NEAR(p.y, 0, 1e-5);
  EXPECT_NEAR(p.z, distance(eye, look), 1e-5);
  test::expectNear(w2c(eye), Point3f(0, 0, 0), 1e-5f);
}

TEST(PerspectiveCamera, ThinLensRaysConvergeAtTheFocalDistance) {
  const Float focal = 5;
  ParamSet ps;
  ps.add(test::floats("lensradius", {0.25f}));
  ps.add(test::floats("focaldistance", {focal}));
  ps.add(test::floats("fov", {45}));
  Point3f eye(1, 1, 1), look(1, 1, 10);
  Transform w2c = lookAt(eye, look, Vector3f(0, 1, 0));
  auto cam = makeCamera(ps, w2c, {80, 60});
  for (Point2f film : {Point2f(40, 30), Point2f(3.5f, 57.25f), Point2f(77, 2)}) {
    CameraSample s = test::cameraSample(film.x, film.y);
    s.pLens = Point2f(0.5f, 0.5f);  // the lens centre: the pinhole ray
    Ray centre;
    cam->generateRay(s, &centre);
    Point3f focus = centre(((eye.z + focal) - centre.o.z) / centre.d.z);
    Float spread = 0;
    for (Point2f u :
         {Point2f(0.1f, 0.2f), Point2f(0.9f, 0.5f), Point2f(0.3f, 0.95f), Point2f(0.01f, 0.01f)}) {
      s.pLens = u;
      Ray r;
      cam->generateRay(s, &r);
      EXPECT_NEAR(r.d.length(), 1, 1e-6);
      Point3f p = r(((eye.z + focal) - r.o.z) / r.d.z);
      test::expectNear(p, focus, 2e-5f);
      spread = std::max(spread, distance(r.o, centre.o));
    }
    EXPECT_GT(spread, 0.1f);  // the rays really start across the lens
    EXPECT_LE(spread, 2 * 0.25f + 1e-3f);
  }
}

// The renderer lets the sampler pass over the lens dimensions for a camera that says it does not
// read them: a pinhole's rays must then be the same for every lens sample, a thin lens's must not.
TEST(PerspectiveCamera, OnlyAThinLensReadsTheLensSample) {
  Transform w2c = lookAt(Point3f(0, 0, 0), Point3f(0, 0, 1), Vector3f(0, 1, 0));
  ParamSet pinholeParams;
  auto pinhole = makeCamera(pinholeParams, w2c, {64, 48});
  EXPECT_FALSE(pinhole->readsLensSample());
  ParamSet lensParams;
  lensParams.add(test::floats("lensradius", {0.1f}));
  lensParams.add(test::floats("focaldistance", {3}));
  auto thinLens = makeCamera(lensParams, w2c, {64, 48});
  EXPECT_TRUE(thinLens->readsLensSample());
  EXPECT_TRUE(test::rayIgnoresLensSample(*pinhole, 10.25f, 40.5f));
  EXPECT_FALSE(test::rayIgnoresLensSample(*thinLens, 10.25f, 40.5f));
}

TEST(PerspectiveCamera, ClippingPlanesAndShutter) {
  ParamSet ps;
  ps.add(test::floats("hither", {0.5f}));
  ps.add(test::floats("yon", {20}));
  ps.add(test::floats("shutteropen", {1}));
  ps.add(test::floats("shutterclose", {3}));
  // cameraToWorld with a uniform scale: the direction must still be unit length, and tMax must
  // still reach the yon plane.
  Transform w2c = scale(0.5f, 0.5f, 0.5f) * translate(Vector3f(0, 0, -1));
  auto cam = makeCamera(ps, w2c, {100, 100});
  CameraSample s = test::cameraSample(10, 80);
  s.time = 0.25f;
  Ray r;
  cam->generateRay(s, &r);
  EXPECT_FLOAT_EQ(r.time, 1.5f);
  EXPECT_NEAR(r.d.length(), 1, 1e-6);
  EXPECT_NEAR(w2c(r.o).z, 0.5f, 1e-5);
  EXPECT_NEAR(w2c(r(r.tMax)).z, 20, 1e-3);
}

TEST(PerspectiveCamera, AnalyticDifferentialsMatchFiniteDifferences) {
  for (Float lens : {0.f, 0.3f}) {
    ParamSet ps;
    ps.add(test::floats("lensradius", {lens}));
    ps.add(test::floats("focaldistance", {4}));
    ps.add(test::floats("fov", {70}));
    auto cam = makeCamera(ps, lookAt(Point3f(0, 1, -3), Point3f(0.5f, 0, 0), Vector3f(0, 1, 0)),
                          {160, 90});
    CameraSample s = test::cameraSample(31.25f, 70.5f);
    s.pLens = Point2f(0.8f, 0.35f);
    RayDifferential analytic, generic;
    cam->generateRayDifferential(s, &analytic);
    cam->Camera::generateRayDifferential(s, &generic);  // the base class: three generateRays
    ASSERT_TRUE(analytic.hasDifferentials);
    ASSERT_TRUE(generic.hasDifferentials);
    test::expectNear(analytic.o, generic.o, 1e-6f);
    test::expectNear(analytic.d, generic.d, 1e-6f);
    test::expectNear(analytic.rxOrigin, generic.rxOrigin, 1e-5f);
    test::expectNear(analytic.ryOrigin, generic.ryOrigin, 1e-5f);
    test::expectNear(analytic.rxDirection, generic.rxDirection, 1e-5f);
    test::expectNear(analytic.ryDirection, generic.ryDirection, 1e-5f);
    // One pixel is a small but nonzero angle.
    Float ax = angleBetween(analytic.d, analytic.rxDirection);
    EXPECT_GT(ax, 1e-4f);
    EXPECT_LT(ax, 0.02f);
  }
}

TEST(PerspectiveCamera, ScreenWindowAndFrameAspectRatio) {
  // An explicit screen window [0 1 0 1] makes the top-left image corner look along +z.
  ParamSet ps;
  ps.add(test::floats("screenwindow", {0, 1, 0, 1}));
  auto cam = makeCamera(ps, Transform(), {50, 50});
  Ray r;
  cam->generateRay(test::cameraSample(0, 50), &r);
  test::expectNear(r.d, Vector3f(0, 0, 1), 1e-6f);
  // frameaspectratio 2 on a square image: the horizontal extent is doubled.
  ParamSet fa;
  fa.add(test::floats("frameaspectratio", {2}));
  fa.add(test::floats("fov", {90}));
  cam = makeCamera(fa, Transform(), {50, 50});
  cam->generateRay(test::cameraSample(0, 25), &r);
  EXPECT_NEAR(-r.d.x / r.d.z, 2, 1e-5);
  cam->generateRay(test::cameraSample(25, 0), &r);
  EXPECT_NEAR(r.d.y / r.d.z, 1, 1e-5);
  EXPECT_EQ(defaultScreenWindow(0.5f).pMax.y, 2.f);
}

TEST(CameraFactory, ErrorsAndHalfFov) {
  try {
    createCamera("fisheye", ParamSet(), Transform(), {10, 10}, FileLoc{"c.pbrt", 8, 1});
    FAIL();
  } catch (const SceneError& e) {
    std::string what = e.what();
    EXPECT_NE(what.find("c.pbrt:8:1"), std::string::npos);
    EXPECT_NE(what.find("fisheye"), std::string::npos);
    for (const char* known : {"perspective", "orthographic", "environment"})
      EXPECT_NE(what.find(known), std::string::npos) << what;
  }
  ParamSet bad;
  bad.add(test::floats("fov", {180}));
  EXPECT_THROW(makeCamera(bad, Transform(), {10, 10}), SceneError);
  ParamSet sw;
  sw.add(test::floats("screenwindow", {0, 1, 0}));
  EXPECT_THROW(makeCamera(sw, Transform(), {10, 10}), SceneError);
  ParamSet half;
  half.add(test::floats("halffov", {15}));
  auto cam = makeCamera(half, Transform(), {10, 10});
  auto& pc = dynamic_cast<PerspectiveCamera&>(*cam);
  EXPECT_FLOAT_EQ(pc.options().fov, 30);
  EXPECT_EQ(pc.shutterOpen(), 0.f);
  EXPECT_EQ(pc.shutterClose(), 1.f);
}

}  // namespace
}  // namespace candela
