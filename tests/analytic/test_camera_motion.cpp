// Camera motion blur (pbrt 2e §6.1): a camera whose CTM differs at the two TransformTimes keys
// takes each ray to world space by the camera-to-world transform at the ray's time. Checked at the
// ray level (the keys and their midpoint, for every camera kind, differentials included), at the
// image level against the closed-form smear of a sharp edge seen by a translating orthographic
// camera, and for determinism across thread counts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "cameras/camera.h"
#include "support/geometry_expect.h"
#include "support/render_scene.h"

namespace candela {
namespace {

// A 20 x 10 image; the options block's CTM is `startCtm` at time 0 and `endCtm` at time 1.
std::string cameraScene(const std::string& camera, const std::string& startCtm,
                        const std::string& endCtm) {
  return std::string("TransformTimes 0 1\n")
      .append("ActiveTransform StartTime\n")
      .append(startCtm)
      .append("\nActiveTransform EndTime\n")
      .append(endCtm)
      .append("\nActiveTransform All\n")
      .append(camera)
      .append("\nFilm \"image\" \"integer xresolution\" [20] \"integer yresolution\" [10]\n")
      .append("WorldBegin\nWorldEnd\n");
}

// The CTM is world-to-camera, so Translate 1 2 3 puts the camera at (-1, -2, -3) and
// Translate -3 0 5 at (3, 0, -5); half way through the shutter it is at (1, -1, -4).
const char* kStartTranslate = "Translate 1 2 3";
const char* kEndTranslate = "Translate -3 0 5";
const Point3f kStartEye(-1, -2, -3), kEndEye(3, 0, -5), kMidEye(1, -1, -4);

// With hither 0 the centre pixel's ray leaves from the camera's origin for all three cameras
// (the orthographic camera's centre film point is the origin too).
TEST(CameraMotion, RaysLeaveFromTheKeyPositionsAndTheirMidpoint) {
  for (const char* camera : {"Camera \"perspective\" \"float hither\" [0]",
                             "Camera \"orthographic\" \"float hither\" [0]",
                             "Camera \"environment\" \"float hither\" [0]"}) {
    SCOPED_TRACE(camera);
    auto built = test::buildSceneText(cameraScene(camera, kStartTranslate, kEndTranslate));
    const Camera& cam = *built.job().camera;
    Ray r;
    // The keys themselves are not interpolated (AnimatedTransform::interpolate returns them), so
    // the origins are exact.
    cam.generateRay(test::cameraSample(10, 5, Point2f(0.5f, 0.5f), 0), &r);
    EXPECT_EQ(r.o, kStartEye);
    EXPECT_EQ(r.time, 0);
    cam.generateRay(test::cameraSample(10, 5, Point2f(0.5f, 0.5f), 1), &r);
    EXPECT_EQ(r.o, kEndEye);
    EXPECT_EQ(r.time, 1);
    // Pure translation interpolates linearly; 1e-6 allows for the decomposition's rounding.
    cam.generateRay(test::cameraSample(10, 5, Point2f(0.5f, 0.5f), 0.5f), &r);
    test::expectNear(r.o, kMidEye, 1e-6f, "midpoint");
    EXPECT_EQ(r.time, 0.5f);

    // The differential rays move with the camera: against a still camera at the midpoint, the
    // same offsets from the main ray and the same directions.
    auto still = test::buildSceneText(cameraScene(camera, "Translate -1 1 4", "Translate -1 1 4"));
    RayDifferential moving, fixed;
    cam.generateRayDifferential(test::cameraSample(7.25f, 3.5f, Point2f(0.5f, 0.5f), 0.5f),
                                &moving);
    still.job().camera->generateRayDifferential(
        test::cameraSample(7.25f, 3.5f, Point2f(0.5f, 0.5f), 0.5f), &fixed);
    ASSERT_TRUE(moving.hasDifferentials);
    ASSERT_TRUE(fixed.hasDifferentials);
    test::expectNear(moving.o, fixed.o, 1e-6f, "main origin");
    test::expectNear(moving.d, fixed.d, 1e-6f, "main direction");
    test::expectNear(moving.rxOrigin, fixed.rxOrigin, 1e-6f, "x origin");
    test::expectNear(moving.ryOrigin, fixed.ryOrigin, 1e-6f, "y origin");
    test::expectNear(moving.rxDirection, fixed.rxDirection, 1e-6f, "x direction");
    test::expectNear(moving.ryDirection, fixed.ryDirection, 1e-6f, "y direction");
  }
}

TEST(CameraMotion, ShutterIntervalPicksTheTimeOfTheMotion) {
  // Shutter [0.25, 0.75] within TransformTimes 0 1: sample time 0 is a quarter of the way.
  auto built = test::buildSceneText(
      cameraScene("Camera \"perspective\" \"float hither\" [0] \"float shutteropen\" [0.25] "
                  "\"float shutterclose\" [0.75]",
                  kStartTranslate, kEndTranslate));
  Ray r;
  built.job().camera->generateRay(test::cameraSample(10, 5, Point2f(0.5f, 0.5f), 0), &r);
  EXPECT_EQ(r.time, 0.25f);
  test::expectNear(r.o, Point3f(0, -1.5f, -3.5f), 1e-6f, "quarter");
  built.job().camera->generateRay(test::cameraSample(10, 5, Point2f(0.5f, 0.5f), 1), &r);
  test::expectNear(r.o, Point3f(2, -0.5f, -4.5f), 1e-6f, "three quarters");
}

// A turning camera (world-to-camera Rotate 90 about y at the end, so camera-to-world turns by -90
// degrees): the centre ray and its x differential turn by -90 s degrees at time s, as they would
// for a still camera turned that far.
TEST(CameraMotion, TurningCameraTurnsItsRaysAndDifferentials) {
  auto built = test::buildSceneText(cameraScene("Camera \"perspective\" \"float fov\" [40]",
                                                "Rotate 0 0 1 0", "Rotate 90 0 1 0"));
  const Camera& cam = *built.job().camera;
  for (Float s : {0.f, 0.3f, 0.5f, 1.f}) {
    SCOPED_TRACE(s);
    Float angle = -90 * s;
    Vector3f want(std::sin(radians(angle)), 0, std::cos(radians(angle)));
    RayDifferential r;
    cam.generateRayDifferential(test::cameraSample(10, 5, Point2f(0.5f, 0.5f), s), &r);
    test::expectNear(r.d, want, 2e-6f, "centre direction");
    char still[64];
    std::snprintf(still, sizeof still, "Rotate %.9g 0 1 0", double(-angle));
    auto fixed = test::buildSceneText(
        cameraScene("Camera \"perspective\" \"float fov\" [40]", still, still));
    RayDifferential f;
    fixed.job().camera->generateRayDifferential(test::cameraSample(10, 5, Point2f(0.5f, 0.5f), s),
                                                &f);
    test::expectNear(r.rxDirection, f.rxDirection, 2e-6f, "x differential");
    test::expectNear(r.ryDirection, f.ryDirection, 2e-6f, "y differential");
  }
}

// ---- The smear of a sharp edge --------------------------------------------------------------

// An orthographic camera over the screen window x in [-2, 2] (kXRes pixels of width kPixel)
// looking down +z at an emitting half-plane x > 0 (black elsewhere). Its camera-to-world
// translation along x goes from kStartX to kStartX + kTravel over the shutter, so the ray through
// screen x at time t lands on world x = sx + kStartX + kTravel t.
constexpr int kXRes = 32, kYRes = 4, kStrata = 16, kSpp = kStrata * kStrata;
constexpr double kPixel = 4.0 / kXRes, kStartX = 0.53, kTravel = 1;

std::string edgeScene(double travel) {
  char buf[1024];
  std::snprintf(buf, sizeof buf,
                "TransformTimes 0 1\n"
                "ActiveTransform StartTime\nTranslate %.17g 0 0\n"
                "ActiveTransform EndTime\nTranslate %.17g 0 0\n"
                "ActiveTransform All\n"
                "Camera \"orthographic\" \"float screenwindow\" [-2 2 -0.25 0.25]\n"
                "Film \"image\" \"integer xresolution\" [%d] \"integer yresolution\" [%d]\n"
                "Sampler \"stratified\" \"integer xsamples\" [%d] \"integer ysamples\" [%d]\n"
                "PixelFilter \"box\"\n"
                "WorldBegin\n"
                "AreaLightSource \"diffuse\" \"rgb L\" [1 1 1] \"bool twosided\" [\"true\"]\n"
                "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3]\n"
                "  \"point P\" [0 -10 5  100 -10 5  100 10 5  0 10 5]\n"
                "WorldEnd\n",
                -kStartX, -(kStartX + travel), kXRes, kYRes, kStrata, kStrata);
  return buf;
}

// P(h U + d T <= z) for independent U, T uniform on [0, 1]: the distribution of a sum of
// uniforms on [0, h] and [0, d], a trapezoid's integral (d = 0 is a single uniform).
double sumOfUniformsCdf(double z, double h, double d) {
  if (d == 0) return std::clamp(z / h, 0.0, 1.0);
  double a = std::min(h, d), b = std::max(h, d);
  if (z <= 0) return 0;
  if (z <= a) return z * z / (2 * h * d);
  if (z <= b) return (z - a / 2) / b;
  if (z < a + b) return 1 - (a + b - z) * (a + b - z) / (2 * h * d);
  return 1;
}

// The expected value of pixel column i, in units of the white side's: the fraction of its
// footprint and the shutter that sees x > 0. The box filter of radius 1/2 spreads the pixel's
// samples uniformly over it (u in [0, 1)) and time is uniform over the shutter, so it is
// P(-2 + kPixel (i + u) + kStartX + travel t > 0) = 1 - P(kPixel u + travel t <= z).
double expectedCoverage(int i, double travel) {
  double z = 2 - kStartX - kPixel * i;
  return 1 - sumOfUniformsCdf(z, kPixel, travel);
}

TEST(CameraMotion, ClosedFormCoverageMatchesAMidpointRule) {
  // Guards the closed form above with a 400 x 400 midpoint rule over (u, t).
  for (double travel : {0.0, 0.06, kTravel})
    for (int i = 0; i < kXRes; ++i) {
      constexpr int n = 400;
      double sum = 0;
      for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b)
          sum += -2 + kPixel * (i + (a + 0.5) / n) + kStartX + travel * (b + 0.5) / n > 0;
      EXPECT_NEAR(expectedCoverage(i, travel), sum / (n * n), 2.0 / n) << i << " " << travel;
    }
}

// Pixel values, in units of a fully white pixel's, with their alphas.
struct EdgeImage {
  double value[kYRes][kXRes], alpha[kYRes][kXRes];
};

EdgeImage renderEdge(double travel) {
  test::TestRenderOptions opt;
  opt.build.seed = 11;
  auto r = test::renderSceneText(edgeScene(travel), opt);
  const Film& film = r.film();
  EdgeImage img;
  double white = film.pixelValue(Point2i(kXRes - 1, 0))[1];
  EXPECT_NEAR(white, 1, 0.05);  // "rgb L" [1 1 1] seen straight on
  for (int y = 0; y < kYRes; ++y)
    for (int x = 0; x < kXRes; ++x) {
      Point2i p(x, y);
      img.alpha[y][x] = film.pixelAlpha(p);
      img.value[y][x] = film.pixelValue(p)[1] / white;
      // Every sample sees either the white side or nothing, so value and alpha agree.
      EXPECT_NEAR(img.value[y][x], img.alpha[y][x], 1e-5) << x << "," << y;
    }
  return img;
}

TEST(CameraMotion, TranslatingCameraSmearsAnEdgeIntoTheClosedFormRamp) {
  EdgeImage img = renderEdge(kTravel);
  // The stratified sampler places the pixel positions (16 x 16 strata) and the times (256
  // strata) each stratified, paired by independent random permutations: Latin hypercube sampling
  // in the two inputs, whose variance is at most n / (n - 1) times that of n independent samples
  // (Owen 1997). A pixel of expected coverage e thus has standard deviation at most
  // sqrt(e (1 - e) / (n - 1)); each pixel must be within 5 of those (none at all where e is 0 or
  // 1: then every sample agrees).
  double maxError = 0, maxZ = 0;
  int band = 0;
  for (int x = 0; x < kXRes; ++x) {
    double e = expectedCoverage(x, kTravel);
    double sigma = std::sqrt(e * (1 - e) / (kSpp - 1));
    band += e > 0 && e < 1;
    for (int y = 0; y < kYRes; ++y) {
      double err = std::abs(img.value[y][x] - e);
      maxError = std::max(maxError, err);
      if (sigma > 0) maxZ = std::max(maxZ, err / sigma);
      EXPECT_LE(err, 5 * sigma + 1e-6)
          << "pixel " << x << "," << y << ": " << img.value[y][x] << ", expected " << e;
    }
  }
  std::printf("[ info ] %d-pixel ramp: largest error %.4f (%.2f sigma)\n", band, maxError, maxZ);
  // The edge sweeps 8 pixels (raster 11.76 to 3.76), so 9 columns are partly white.
  EXPECT_EQ(band, 9);
}

TEST(CameraMotion, StillCameraSeesASharpEdge) {
  EdgeImage img = renderEdge(0);
  // Only the column holding the edge (raster 11.76) is grey, at 0.24. The edge falls in one of
  // its 16 stratum columns, whose 16 samples are the only ones that can go either way: the
  // error is at most 16 / 256.
  int grey = 0;
  double edgeError = 0;
  for (int x = 0; x < kXRes; ++x) {
    double e = expectedCoverage(x, 0);
    grey += e > 0 && e < 1;
    for (int y = 0; y < kYRes; ++y) {
      if (e == 0 || e == 1) {
        EXPECT_EQ(img.value[y][x], e) << x << "," << y;
        continue;
      }
      edgeError = std::max(edgeError, std::abs(img.value[y][x] - e));
      EXPECT_LE(std::abs(img.value[y][x] - e), 1.0 / kStrata + 1e-6) << x << "," << y;
    }
  }
  std::printf("[ info ] edge pixel error %.4f\n", edgeError);
  EXPECT_EQ(grey, 1);
  EXPECT_NEAR(expectedCoverage(11, 0), 0.24, 1e-9);
}

// ---- Determinism and the still case --------------------------------------------------------

std::string litScene(const std::string& startLookAt, const std::string& endLookAt) {
  return std::string("TransformTimes 0 1\nActiveTransform StartTime\n")
      .append(startLookAt)
      .append("\nActiveTransform EndTime\n")
      .append(endLookAt)
      .append(R"(
ActiveTransform All
Camera "perspective" "float fov" [45]
Film "image" "integer xresolution" [48] "integer yresolution" [36]
Sampler "stratified" "integer xsamples" [3] "integer ysamples" [3]
SurfaceIntegrator "directlighting"
WorldBegin
LightSource "point" "point from" [2 -4 6] "rgb I" [40 40 40]
Material "matte" "rgb Kd" [0.6 0.6 0.6]
Shape "trianglemesh" "integer indices" [0 1 2 0 2 3]
  "point P" [-6 -6 -0.7  6 -6 -0.7  6 6 -0.7  -6 6 -0.7]
Material "matte" "rgb Kd" [0.9 0.2 0.1]
Shape "sphere" "float radius" [0.7]
WorldEnd
)");
}

const char* kLookFrom = "LookAt 0 -9 4  0 0 0.3  0 0 1";
const char* kLookFromElsewhere = "LookAt 2 -8 5  0.3 0 0.3  0 0 1";

int countDifferences(const Film& a, const Film& b) {
  Bounds2i px = a.pixelBounds();
  int differ = 0;
  for (int y = px.pMin.y; y < px.pMax.y; ++y)
    for (int x = px.pMin.x; x < px.pMax.x; ++x) {
      Point2i p(x, y);
      for (int c = 0; c < 3; ++c) differ += a.pixelValue(p)[c] != b.pixelValue(p)[c];
      differ += a.pixelAlpha(p) != b.pixelAlpha(p);
    }
  return differ;
}

TEST(CameraMotion, MovingCameraRenderIsTheSameForOneAndTwoThreads) {
  std::string scene = litScene(kLookFrom, kLookFromElsewhere);
  test::TestRenderOptions one, two;
  one.build.seed = two.build.seed = 3;
  one.render.nThreads = 1;
  two.render.nThreads = 2;
  one.render.tileSize = two.render.tileSize = 8;
  auto a = test::renderSceneText(scene, one), b = test::renderSceneText(scene, two);
  EXPECT_EQ(countDifferences(a.film(), b.film()), 0);
  // And the motion shows: the still camera's picture differs in most pixels.
  auto still = test::renderSceneText(litScene(kLookFrom, kLookFrom), one);
  int differ = countDifferences(a.film(), still.film());
  std::printf("[ info ] %d of %d values differ from the still camera's\n", differ, 48 * 36 * 4);
  EXPECT_GT(differ, 48 * 36);
}

TEST(CameraMotion, EqualKeysAreBitIdenticalToNoMotion) {
  std::string plain = litScene(kLookFrom, kLookFrom);
  plain.replace(0, plain.find("ActiveTransform All"), std::string(kLookFrom).append("\n"));
  test::TestRenderOptions opt;
  opt.build.seed = 3;
  auto a = test::renderSceneText(plain, opt);
  auto b = test::renderSceneText(litScene(kLookFrom, kLookFrom), opt);
  EXPECT_EQ(countDifferences(a.film(), b.film()), 0);
}

}  // namespace
}  // namespace candela
