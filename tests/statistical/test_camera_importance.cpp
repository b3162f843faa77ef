// Perspective camera importance (pbrt 3e §16.1.1): We integrates to 1 over lens and directions
// (Monte Carlo with directions uniform on the sphere, independent of pdfWe; Z-test at significance
// 0.01 Šidák-corrected over the cases); sampleWi's density is the lens's solid angle (the mean of
// 1 / pdf over lens samples is the solid angle the lens disk subtends, Z-test likewise); pdfWe's
// densities generate the camera's own rays; the raster position We and sampleWi report is the one
// generateRay started from. Fixed seeds.
#include <gtest/gtest.h>

#include <cmath>

#include "cameras/camera.h"
#include "core/rng.h"
#include "core/sampling.h"
#include "support/param_items.h"
#include "support/tail_probabilities.h"

namespace candela {
namespace {

constexpr int kZCases = 4;

std::unique_ptr<Camera> makeCamera(Float lensRadius, Point2i res) {
  ParamSet ps;
  ps.add(test::floats("fov", {50}));
  if (lensRadius > 0) {
    ps.add(test::floats("lensradius", {lensRadius}));
    ps.add(test::floats("focaldistance", {3}));
  }
  Transform worldToCamera = lookAt(Point3f(1, 2, -3), Point3f(0.5f, 0, 1), Vector3f(0.2f, 1, 0));
  return createCamera("perspective", ps, inverse(worldToCamera), res, FileLoc{"c.pbrt", 1, 1});
}

void expectZ(double sum, double sumSq, int n, double expected) {
  double mean = sum / n, var = (sumSq - sum * mean) / (n - 1);
  double z = (mean - expected) / std::sqrt(var / n);
  EXPECT_GT(stats::normalTwoSidedTail(z), stats::sidak(0.01, kZCases))
      << "mean " << mean << ", expected " << expected << ", z " << z;
}

// ∫_lens ∫_S² We cos θ dω dA = 1: lens points uniform on the lens disk, directions uniform on the
// sphere, estimator We cos θ A_lens 4π.
void checkImportanceIntegratesToOne(Float lensRadius, uint64_t seed) {
  auto cam = makeCamera(lensRadius, {64, 48});
  const CameraImportance* imp = cam->importance();
  ASSERT_NE(imp, nullptr);
  Vector3f axis = imp->axis(0);
  Vector3f x, y;
  coordinateSystem(axis, &x, &y);
  Point3f centre = imp->lensPoint(Ray(Point3f(1, 2, -3), axis, kInfinity, 0));
  Float lensArea = lensRadius > 0 ? kPi * lensRadius * lensRadius : 1;
  RNG rng(seed);
  const int n = 400000;
  double sum = 0, sumSq = 0;
  for (int i = 0; i < n; ++i) {
    Point2f l = sampleUniformDiskConcentric(Point2f(rng.uniformFloat(), rng.uniformFloat()));
    // A lens point: its position in the lens plane only matters through the camera's frame, so
    // any orthonormal pair in the plane serves.
    Point3f p = centre + (x * l.x + y * l.y) * lensRadius;
    Vector3f w = sampleUniformSphere(Point2f(rng.uniformFloat(), rng.uniformFloat()));
    Point2f raster;
    double v = imp->We(Ray(p, w, kInfinity, 0), &raster)[0] * std::max(Float(0), dot(w, axis)) *
               lensArea * 4 * kPi;
    sum += v;
    sumSq += v * v;
  }
  expectZ(sum, sumSq, n, 1);
}

TEST(CameraImportance, IntegratesToOnePinhole) { checkImportanceIntegratesToOne(0, 1); }
TEST(CameraImportance, IntegratesToOneThinLens) { checkImportanceIntegratesToOne(0.2f, 2); }

// E[1 / pdf] over sampleWi's lens points is the solid angle of the lens disk from ref; on the
// axis at distance h, 2π (1 - h / sqrt(h² + r²)). The lens must be seen through the film, so ref
// is far enough ahead (the focus plane is at 3).
TEST(CameraImportance, SampleWiDensityIsTheLensSolidAngle) {
  Float r = 0.2f;
  auto cam = makeCamera(r, {64, 48});
  const CameraImportance* imp = cam->importance();
  Vector3f axis = imp->axis(0);
  Point3f centre = imp->lensPoint(Ray(Point3f(1, 2, -3), axis, kInfinity, 0));
  double h = 2.5;
  Interaction ref(centre + axis * Float(h), 0);
  RNG rng(3);
  const int n = 100000;
  double sum = 0, sumSq = 0;
  for (int i = 0; i < n; ++i) {
    CameraWiSample s = imp->sampleWi(ref, Point2f(rng.uniformFloat(), rng.uniformFloat()));
    ASSERT_GT(s.pdf, 0);
    ASSERT_FALSE(s.We.isBlack());
    double v = 1 / double(s.pdf);
    sum += v;
    sumSq += v * v;
  }
  expectZ(sum, sumSq, n, 2 * M_PI * (1 - h / std::sqrt(h * h + double(r) * r)));
}

// The camera's rays: pdfWe is 1 / A_lens per area and 1 / (A_film cos³θ) per solid angle, We and
// sampleWi (from a point on the ray, with the ray's lens sample) give back the raster position
// the ray was generated for, sampleWi's direction is the ray's reversed, and the importance is
// the same both ways.
void checkCameraRays(Float lensRadius, uint64_t seed) {
  Point2i res(80, 60);
  auto cam = makeCamera(lensRadius, res);
  const CameraImportance* imp = cam->importance();
  RNG rng(seed);
  for (int i = 0; i < 2000; ++i) {
    CameraSample cs;
    cs.pFilm = Point2f(rng.uniformFloat() * res.x, rng.uniformFloat() * res.y);
    cs.pLens = Point2f(rng.uniformFloat(), rng.uniformFloat());
    Ray ray;
    cam->generateRay(cs, &ray);
    Point2f raster;
    Spectrum we = imp->We(ray, &raster);
    ASSERT_GT(we[0], 0);
    EXPECT_NEAR(raster.x, cs.pFilm.x, 2e-3f);
    EXPECT_NEAR(raster.y, cs.pFilm.y, 2e-3f);
    Float pdfPos, pdfDir;
    imp->pdfWe(ray, &pdfPos, &pdfDir);
    Float cosTheta = dot(ray.d, imp->axis(0));
    Float lensArea = lensRadius > 0 ? kPi * lensRadius * lensRadius : 1;
    EXPECT_NEAR(pdfPos, 1 / lensArea, 1e-4f / lensArea);
    // We = 1 / (A_film A_lens cos⁴θ) and pdfDir = 1 / (A_film cos³θ).
    EXPECT_NEAR(we[0] * lensArea * cosTheta, pdfDir, 1e-4f * pdfDir);

    Interaction ref(ray(Float(1) + 4 * rng.uniformFloat()), 0);
    CameraWiSample s = imp->sampleWi(ref, cs.pLens);
    ASSERT_GT(s.pdf, 0);
    EXPECT_NEAR(s.pRaster.x, cs.pFilm.x, 2e-3f);
    EXPECT_NEAR(s.pRaster.y, cs.pFilm.y, 2e-3f);
    EXPECT_NEAR(dot(s.wi, -ray.d), 1, 1e-5f);
    EXPECT_NEAR(s.We[0], we[0], 1e-3f * we[0]);
    EXPECT_NEAR(distance(s.pLens.p, imp->lensPoint(ray)), 0, 1e-4f);
  }
}

TEST(CameraImportance, CameraRaysPinhole) { checkCameraRays(0, 4); }
TEST(CameraImportance, CameraRaysThinLens) { checkCameraRays(0.2f, 5); }

// Behind the camera or outside the field of view: no importance and no density.
TEST(CameraImportance, NothingOffTheFilm) {
  auto cam = makeCamera(0, {64, 48});
  const CameraImportance* imp = cam->importance();
  Vector3f axis = imp->axis(0);
  Point3f eye(1, 2, -3);
  Point2f raster;
  EXPECT_TRUE(imp->We(Ray(eye, -axis, kInfinity, 0), &raster).isBlack());
  Vector3f side, up;
  coordinateSystem(axis, &side, &up);
  Vector3f wide = normalize(axis + side * 3);  // 71.6° off axis, beyond the 25° half fov
  EXPECT_TRUE(imp->We(Ray(eye, wide, kInfinity, 0), &raster).isBlack());
  Float pdfPos, pdfDir;
  imp->pdfWe(Ray(eye, wide, kInfinity, 0), &pdfPos, &pdfDir);
  EXPECT_EQ(pdfDir, 0);
  CameraWiSample s = imp->sampleWi(Interaction(eye - axis * 2, 0), Point2f(0.5f, 0.5f));
  EXPECT_EQ(s.pdf, 0);
}

TEST(CameraImportance, OnlyThePerspectiveCameraHasIt) {
  Point2i res(16, 16);
  FileLoc loc{"c.pbrt", 1, 1};
  EXPECT_EQ(createCamera("orthographic", ParamSet(), Transform(), res, loc)->importance(), nullptr);
  EXPECT_EQ(createCamera("environment", ParamSet(), Transform(), res, loc)->importance(), nullptr);
  EXPECT_NE(createCamera("perspective", ParamSet(), Transform(), res, loc)->importance(), nullptr);
}

}  // namespace
}  // namespace candela
