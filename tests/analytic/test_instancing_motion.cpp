// Object instancing and motion blur, end to end from scene text: instances render as the same
// shapes written out under the same transforms (up to float rounding), hits report the
// prototype's primitive, a sphere translated over the shutter renders as the smear whose
// coverage follows from the closed form below, a zero-length shutter freezes it at its start
// position, and TransformTimes with equal keys changes nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "accel/scene_geometry.h"
#include "support/render_scene.h"

namespace candela {
namespace {

// ---- Instances against the same shapes written out -----------------------------------------

const char* kViewAndLight = R"(
LookAt 0 -9 4  0 0 0.3  0 0 1
Camera "perspective" "float fov" [45]
Film "image" "integer xresolution" [64] "integer yresolution" [48]
Sampler "random" "integer pixelsamples" [4]
SurfaceIntegrator "directlighting"
WorldBegin
LightSource "point" "point from" [2 -4 6] "rgb I" [40 40 40]
Material "matte" "rgb Kd" [0.6 0.6 0.6]
Shape "trianglemesh" "integer indices" [0 1 2 0 2 3]
  "point P" [-6 -6 -0.7  6 -6 -0.7  6 6 -0.7  -6 6 -0.7]
)";

// The prototype: a sphere and a small square above and beside it, in its own space.
const char* kPrototypeBody = R"(
  Shape "sphere" "float radius" [0.7]
  Translate 0 0 1.2
  Material "matte" "rgb Kd" [0.9 0.2 0.1]
  Shape "trianglemesh" "integer indices" [0 1 2 0 2 3]
    "point P" [0.7 -0.3 0  1.3 -0.3 0  1.3 0.3 0  0.7 0.3 0]
)";

const char* kPlacements[] = {
    "Translate -2 0 0", "Translate 2 0 0 Rotate 40 0 0 1 Scale 1 1 1.5",
    "Translate 0 2 0 Scale -1 1 1",  // mirrored
};

std::string instancedScene() {
  std::string s = kViewAndLight;
  s += std::string("ObjectBegin \"thing\"\n") + kPrototypeBody + "ObjectEnd\n";
  for (const char* p : kPlacements)
    s += std::string("AttributeBegin\n") + p + "\nObjectInstance \"thing\"\nAttributeEnd\n";
  return s + "WorldEnd\n";
}

std::string flattenedScene() {
  std::string s = kViewAndLight;
  for (const char* p : kPlacements)
    s += std::string("AttributeBegin\n") + p + "\n" + kPrototypeBody + "AttributeEnd\n";
  return s + "WorldEnd\n";
}

TEST(Instancing, RendersLikeTheShapesWrittenOut) {
  test::TestRenderOptions opt;
  opt.build.seed = 5;
  auto inst = test::renderSceneText(instancedScene(), opt);
  auto flat = test::renderSceneText(flattenedScene(), opt);
  const Film &a = inst.film(), &b = flat.film();
  Bounds2i px = a.pixelBounds();
  int pixels = 0, differ = 0, lit = 0;
  double maxRel = 0;
  for (int y = px.pMin.y; y < px.pMax.y; ++y)
    for (int x = px.pMin.x; x < px.pMax.x; ++x) {
      Point2i p(x, y);
      ++pixels;
      EXPECT_EQ(a.pixelAlpha(p), b.pixelAlpha(p)) << x << "," << y;
      for (int c = 0; c < 3; ++c) {
        double va = a.pixelValue(p)[c], vb = b.pixelValue(p)[c];
        lit += c == 0 && vb > 0;
        double rel = std::abs(va - vb) / std::max(1e-3, std::abs(vb));
        maxRel = std::max(maxRel, rel);
        if (rel > 1e-4) ++differ;
      }
    }
  std::printf("[ info ] %d pixels (%d lit), max relative difference %.3g, %d values above 1e-4\n",
              pixels, lit, maxRel, differ);
  EXPECT_GT(lit, pixels / 2);
  EXPECT_EQ(differ, 0);
}

TEST(Instancing, SharesOnePrototypeAndHitsReportItsPrimitives) {
  auto built = test::buildSceneText(instancedScene());
  RenderJob& job = built.job();
  const SceneGeometry& g = job.geometry;
  ASSERT_EQ(g.prototypes.size(), 1u);
  ASSERT_EQ(g.instances.size(), 3u);
  EXPECT_EQ(g.primitives.size(), 2u);  // the ground
  // Created once, however many instances: one sphere, two triangles of the square.
  EXPECT_EQ(job.stats.shapesByKind["sphere"], 1);
  EXPECT_EQ(job.stats.shapesByKind["triangle"], 4);
  EXPECT_EQ(job.stats.aggregate.counts["instances"], 3);
  EXPECT_EQ(job.stats.aggregate.counts["prototypes"], 1);
  EXPECT_EQ(job.stats.aggregate.counts["embree instance geometries"], 3);
  EXPECT_EQ(job.stats.aggregate.counts["motion instances"], 0);

  const std::vector<Primitive>& protoPrims = g.prototypes[0]->primitives;
  const Aggregate& agg = *job.aggregate;
  // Straight down onto the first instance (Translate -2 0 0): the sphere's top at z = 0.7.
  SurfaceInteraction isect;
  Ray down(Point3f(-2, 0, 5), Vector3f(0, 0, -1));
  ASSERT_TRUE(agg.intersect(down, &isect));
  EXPECT_EQ(isect.primitive, &protoPrims[0]);
  EXPECT_STREQ(isect.primitive->shape->kind(), "sphere");
  EXPECT_NEAR(isect.p.z, 0.7f, 1e-5f);
  EXPECT_NEAR(isect.n.z, 1, 1e-5f);
  EXPECT_NEAR(down.tMax, 4.3f, 1e-5f);
  // Onto its square at x = -2 + 1, z = 1.2.
  Ray onSquare(Point3f(-1, 0.1f, 5), Vector3f(0, 0, -1));
  ASSERT_TRUE(agg.intersect(onSquare, &isect));
  EXPECT_STREQ(isect.primitive->shape->kind(), "triangle");
  EXPECT_GE(isect.primitive, &protoPrims[1]);
  EXPECT_LE(isect.primitive, &protoPrims[2]);
  EXPECT_NEAR(isect.p.z, 1.2f, 1e-5f);
  // The mirrored instance (Translate 0 2 0, Scale -1 1 1): its square is at x = -1, and the
  // sphere's normal still points out of the sphere.
  Ray mirrored(Point3f(-1, 2.1f, 5), Vector3f(0, 0, -1));
  ASSERT_TRUE(agg.intersect(mirrored, &isect));
  EXPECT_STREQ(isect.primitive->shape->kind(), "triangle");
  EXPECT_NEAR(isect.p.x, -1, 1e-5f);
  Ray side(Point3f(5, 2, 0), Vector3f(-1, 0, 0));
  ASSERT_TRUE(agg.intersect(side, &isect));
  EXPECT_EQ(isect.primitive, &protoPrims[0]);
  EXPECT_NEAR(isect.p.x, 0.7f, 1e-5f);
  EXPECT_NEAR(isect.n.x, 1, 1e-5f);
  // The ground is a world primitive.
  Ray ground(Point3f(-4, 4, 5), Vector3f(0, 0, -1));
  ASSERT_TRUE(agg.intersect(ground, &isect));
  EXPECT_EQ(isect.primitive, &g.primitives[1]);
}

// ---- Motion blur --------------------------------------------------------------------------

// A camera at z = -10 looking down +z (world +x to the right), a sphere of radius r whose centre
// moves from (x0, 0, 0) to (x1, 0, 0) over the shutter: only alpha (coverage) is looked at.
constexpr int kXRes = 81, kYRes = 21, kSpp = 64;
constexpr double kFov = 20, kRadius = 0.5, kDistance = 10;

std::string movingSphereScene(double x0, double x1, const std::string& shutter,
                              const std::string& times = "") {
  char buf[1024];
  std::snprintf(buf, sizeof buf,
                "%s\n"
                "LookAt 0 0 -10  0 0 0  0 1 0\n"
                "Camera \"perspective\" \"float fov\" [%g] %s\n"
                "Film \"image\" \"integer xresolution\" [%d] \"integer yresolution\" [%d]\n"
                "Sampler \"random\" \"integer pixelsamples\" [%d]\n"
                "PixelFilter \"box\"\n"
                "WorldBegin\n"
                "AttributeBegin\n"
                "  ActiveTransform StartTime\n  Translate %g 0 0\n"
                "  ActiveTransform EndTime\n  Translate %g 0 0\n"
                "  ActiveTransform All\n"
                "  Shape \"sphere\" \"float radius\" [%g]\n"
                "AttributeEnd\n"
                "WorldEnd\n",
                times.c_str(), kFov, shutter.c_str(), kXRes, kYRes, kSpp, x0, x1, kRadius);
  return buf;
}

// The fraction of the shutter during which the camera ray through screen point (sx, sy) hits the
// sphere, for a centre moving uniformly from x0 to x1 (at constant depth kDistance). With u the
// unit ray direction from the pinhole and C = (x, 0, D), the ray hits when the distance from C to
// the ray is below r: |C|^2 - (C.u)^2 < r^2, a quadratic in x.
double coverageAlongRay(double sx, double sy, double x0, double x1) {
  double tanHalf = std::tan(kFov / 2 * 3.14159265358979323846 / 180);
  double ux = sx * tanHalf, uy = sy * tanHalf, uz = 1;
  double len = std::sqrt(ux * ux + uy * uy + uz * uz);
  ux /= len, uz /= len;
  double D = kDistance, r = kRadius;
  double a = 1 - ux * ux, b = -2 * D * ux * uz, c = D * D * (1 - uz * uz) - r * r;
  double disc = b * b - 4 * a * c;
  if (disc <= 0) return 0;
  double lo = (-b - std::sqrt(disc)) / (2 * a), hi = (-b + std::sqrt(disc)) / (2 * a);
  if (x0 == x1) return (x0 > lo && x0 < hi) ? 1 : 0;
  double overlap = std::min(hi, x1) - std::max(lo, x0);
  return std::max(0.0, overlap) / (x1 - x0);
}

// Expected alpha of pixel (x, y): the coverage averaged over the pixel's area (a box filter of
// radius 1/2 puts each pixel's samples uniformly in it) by a 24 x 24 midpoint rule.
double expectedAlpha(int x, int y, double x0, double x1) {
  double aspect = double(kXRes) / kYRes, sum = 0;
  constexpr int n = 24;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      double rx = x + (i + 0.5) / n, ry = y + (j + 0.5) / n;
      double sx = -aspect + 2 * aspect * rx / kXRes, sy = 1 - 2 * ry / kYRes;
      sum += coverageAlongRay(sx, sy, x0, x1);
    }
  return sum / (n * n);
}

// Moments of an alpha image along x about the image centre c: M0 = sum a, M1 = sum a (x - c),
// M2 = sum a (x - c)^2 over pixel centres. For a render, each pixel's alpha is a mean of kSpp
// hit-or-miss samples, independent between pixels, so each moment has the variance
// sum e (1 - e) / kSpp (x - c)^(2k) with e the expected alpha.
struct Moments {
  double m[3] = {0, 0, 0}, var[3] = {0, 0, 0};
  double centroid() const { return kXRes / 2.0 + m[1] / m[0]; }
  double spread() const { return std::sqrt(m[2] / m[0] - (m[1] / m[0]) * (m[1] / m[0])); }
};
template <typename F>
Moments momentsOf(F alpha) {
  Moments s;
  for (int y = 0; y < kYRes; ++y)
    for (int x = 0; x < kXRes; ++x) {
      double a = alpha(x, y), dx = x + 0.5 - kXRes / 2.0, w = 1;
      for (int k = 0; k < 3; ++k, w *= dx) {
        s.m[k] += a * w;
        s.var[k] += a * (1 - a) / kSpp * w * w;
      }
    }
  return s;
}

// The render's moments within 5 standard deviations of the closed form's.
void expectMomentsMatch(const Film& film, double x0, double x1, const char* what) {
  Moments got = momentsOf([&](int x, int y) { return double(film.pixelAlpha(Point2i(x, y))); });
  Moments want = momentsOf([&](int x, int y) { return expectedAlpha(x, y, x0, x1); });
  std::printf(
      "[ info ] %s: coverage %.2f expected %.2f pixels, centroid x %.3f expected %.3f, spread "
      "%.3f expected %.3f\n",
      what, got.m[0], want.m[0], got.centroid(), want.centroid(), got.spread(), want.spread());
  for (int k = 0; k < 3; ++k)
    EXPECT_LE(std::abs(got.m[k] - want.m[k]), 5 * std::sqrt(want.var[k]) + 1e-9)
        << what << ": moment " << k << " is " << got.m[k] << ", expected " << want.m[k];
}

// Every pixel's alpha within 5 standard deviations of a mean of kSpp hit-or-miss samples.
void expectAlphaMatchesClosedForm(const Film& film, double x0, double x1) {
  int worst = 0;
  double worstZ = 0;
  for (int y = 0; y < kYRes; ++y)
    for (int x = 0; x < kXRes; ++x) {
      double e = expectedAlpha(x, y, x0, x1), a = film.pixelAlpha(Point2i(x, y));
      double sigma = std::sqrt(std::max(e * (1 - e), 1.0 / kSpp) / kSpp);
      double z = std::abs(a - e) / sigma;
      if (z > worstZ) worstZ = z, worst = y * kXRes + x;
      EXPECT_LE(z, 5) << "pixel " << x << "," << y << ": alpha " << a << ", expected " << e;
    }
  std::printf("[ info ] largest deviation %.2f sigma at pixel %d,%d\n", worstZ, worst % kXRes,
              worst / kXRes);
}

TEST(MotionBlur, MovingSphereIsTheClosedFormSmear) {
  const double x0 = -1.5, x1 = 1.5;
  auto r = test::renderSceneText(movingSphereScene(x0, x1, ""));
  EXPECT_EQ(r.job().stats.aggregate.counts["motion instances"], 1);
  expectAlphaMatchesClosedForm(r.film(), x0, x1);
  // Coverage, centroid and extent (second moment) of the smear. The motion is symmetric about
  // the optical axis, so the expected centroid is the image centre.
  expectMomentsMatch(r.film(), x0, x1, "smear");
  Moments want = momentsOf([&](int x, int y) { return expectedAlpha(x, y, x0, x1); });
  Moments sharp = momentsOf([&](int x, int y) { return expectedAlpha(x, y, x0, x0); });
  EXPECT_NEAR(want.centroid(), kXRes / 2.0, 1e-9);
  EXPECT_GT(want.spread(), 3 * sharp.spread());  // a smear, not a sphere
}

TEST(MotionBlur, ZeroLengthShutterFreezesTheStartPosition) {
  const double x0 = -1.5, x1 = 1.5;
  auto r = test::renderSceneText(
      movingSphereScene(x0, x1, "\"float shutteropen\" [0] \"float shutterclose\" [0]"));
  expectAlphaMatchesClosedForm(r.film(), x0, x0);
  // The same picture as the sphere standing at its start position.
  auto still = test::renderSceneText(movingSphereScene(x0, x0, ""));
  int differ = 0;
  for (int y = 0; y < kYRes; ++y)
    for (int x = 0; x < kXRes; ++x)
      differ += r.film().pixelAlpha(Point2i(x, y)) != still.film().pixelAlpha(Point2i(x, y));
  std::printf("[ info ] %d pixels differ from the still sphere\n", differ);
  expectMomentsMatch(r.film(), x0, x0, "frozen");
  EXPECT_LE(differ, 2);  // a silhouette sample may round either way
}

TEST(MotionBlur, ShutterIntervalSelectsThePartOfTheMotion) {
  // TransformTimes 0 2 with the shutter over [1, 2]: the second half of the motion only.
  const double x0 = -1.5, x1 = 1.5;
  auto r = test::renderSceneText(movingSphereScene(
      x0, x1, "\"float shutteropen\" [1] \"float shutterclose\" [2]", "TransformTimes 0 2"));
  expectAlphaMatchesClosedForm(r.film(), 0, x1);
}

TEST(MotionBlur, AnimatedInstanceRendersLikeAnimatedShape) {
  std::string shape = movingSphereScene(-1, 1, "");
  std::string inst = shape;
  // The same motion on an ObjectInstance of a sphere defined at the origin.
  size_t at = inst.find("AttributeBegin");
  inst.insert(at, "ObjectBegin \"ball\"\nShape \"sphere\" \"float radius\" [0.5]\nObjectEnd\n");
  size_t shapeAt = inst.find("  Shape \"sphere\"", inst.find("ActiveTransform All"));
  inst.replace(shapeAt, inst.find('\n', shapeAt) - shapeAt, "  ObjectInstance \"ball\"");
  auto a = test::renderSceneText(shape), b = test::renderSceneText(inst);
  EXPECT_EQ(b.job().stats.aggregate.counts["motion instances"], 1);
  int differ = 0;
  for (int y = 0; y < kYRes; ++y)
    for (int x = 0; x < kXRes; ++x)
      differ += a.film().pixelAlpha(Point2i(x, y)) != b.film().pixelAlpha(Point2i(x, y));
  EXPECT_LE(differ, 2);
}

TEST(MotionBlur, EqualKeysAreBitIdenticalToNoMotion) {
  std::string plain = std::string(kViewAndLight) +
                      "AttributeBegin\nTranslate 0.5 0.2 0\nRotate 20 1 0 0\n" + kPrototypeBody +
                      "AttributeEnd\nWorldEnd\n";
  std::string keyed = "TransformTimes 0 1\n" + std::string(kViewAndLight) +
                      "AttributeBegin\n"
                      "ActiveTransform StartTime\nTranslate 0.5 0.2 0\nRotate 20 1 0 0\n"
                      "ActiveTransform EndTime\nTranslate 0.5 0.2 0\nRotate 20 1 0 0\n"
                      "ActiveTransform All\n" +
                      kPrototypeBody + "AttributeEnd\nWorldEnd\n";
  auto a = test::renderSceneText(plain), b = test::renderSceneText(keyed);
  EXPECT_EQ(b.job().stats.aggregate.counts.count("motion instances"), 0u);
  Bounds2i px = a.film().pixelBounds();
  int differ = 0;
  for (int y = px.pMin.y; y < px.pMax.y; ++y)
    for (int x = px.pMin.x; x < px.pMax.x; ++x) {
      Point2i p(x, y);
      for (int c = 0; c < 3; ++c) differ += a.film().pixelValue(p)[c] != b.film().pixelValue(p)[c];
      differ += a.film().pixelAlpha(p) != b.film().pixelAlpha(p);
    }
  EXPECT_EQ(differ, 0);
}

}  // namespace
}  // namespace candela
