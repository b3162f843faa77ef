// "whitted", "ambientocclusion" and pbrt-v3's "ao" against closed forms. Whitted's scenes are
// noiseless (delta lights, perfect specular surfaces, constant backgrounds), so they are checked to
// float precision; ambient occlusion is a binomial estimate, checked within 4 standard deviations
// of the sample count.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "core/error.h"
#include "support/render_scene.h"
#include "transport/specular_differentials.h"

namespace candela {
namespace {

// One sample per pixel, exactly at the pixel centre, so each pixel is one known camera ray.
const char* kCentreSampler =
    "Sampler \"stratified\" \"integer xsamples\" [1] \"integer ysamples\" [1] "
    "\"bool jitter\" [\"false\"]\n";

std::string quad(const std::string& points) {
  return std::string("Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point P\" [")
      .append(points)
      .append("]\n");
}

std::string scene(const std::string& header, const std::string& integrator,
                  const std::string& world) {
  return std::string(header)
      .append("SurfaceIntegrator ")
      .append(integrator)
      .append("\nWorldBegin\n")
      .append(world)
      .append("WorldEnd\n");
}

std::string whitted(int maxDepth) {
  return std::string("\"whitted\" \"integer maxdepth\" [").append(std::to_string(maxDepth)) + "]";
}

// A measured error for the test report (--gtest_output=xml), to three significant digits.
void recordError(const char* key, double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  ::testing::Test::RecordProperty(key, text);
}

template <typename F>
void forEachPixel(const Film& film, F&& f) {
  Bounds2i b = film.pixelBounds();
  for (int y = b.pMin.y; y < b.pMax.y; ++y)
    for (int x = b.pMin.x; x < b.pMax.x; ++x) f(Point2i(x, y));
}

// --- whitted ---

TEST(Whitted, PointLitDiffusePlaneIsTheClosedForm) {
  // L = (Kd / pi) I cos(theta) / r^2 with cos(theta) = h / r: one sample of a delta light is
  // exact. The orthographic camera looks straight down, so pixel (x, y) sees the plane at its
  // screen position; the value is symmetric about the light's foot, so the image's mirroring
  // does not matter. The plane is just larger than the view: hit points interpolated from
  // far-away vertices would carry their rounding (ulp(100) ~ 1e-5) into r.
  const int res = 8;
  const Float half = 2, h = 1, kd = 0.5f, intensity = 3;
  std::string header = std::string("LookAt 0 0 5  0 0 0  0 1 0\n")
                           .append("Camera \"orthographic\" \"float screenwindow\" [-2 2 -2 2]\n")
                           .append(
                               "Film \"image\" \"integer xresolution\" [8] "
                               "\"integer yresolution\" [8]\n")
                           .append(kCentreSampler);
  std::string world =
      std::string("LightSource \"point\" \"rgb I\" [3 3 3] \"point from\" [0 0 1]\n")
          .append("Material \"matte\" \"rgb Kd\" [0.5 0.5 0.5]\n")
          .append(quad("-2.5 -2.5 0  2.5 -2.5 0  2.5 2.5 0  -2.5 2.5 0"));
  auto r = test::renderSceneText(scene(header, whitted(5), world));
  double worst = 0;
  forEachPixel(r.film(), [&](const Point2i& p) {
    double sx = -half + 2 * half * (p.x + 0.5) / res, sy = -half + 2 * half * (p.y + 0.5) / res;
    double dist = std::sqrt(sx * sx + sy * sy + double(h) * h);
    double expected = kd / kPi * intensity * h / (dist * dist * dist);
    Spectrum v = r.film().pixelValue(p);
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(v[c] - expected) / expected);
  });
  EXPECT_LT(worst, 2e-6);
  recordError("worst_relative_error", worst);
}

// Two facing mirrors of reflectance r that also emit Le (two-sided): a ray between them gathers
// Le at each of its hits, the k-th weighted r^k. Hits happen at depths 0 .. maxdepth-1, so
// L = Le (1 - r^d) / (1 - r) for d = maxdepth >= 1; maxdepth 0 follows no reflection either.
TEST(Whitted, HallOfMirrorsIsTheTruncatedGeometricSeries) {
  std::string header = std::string("LookAt 0 0 0  0 0 1  0 1 0\n")
                           .append("Camera \"perspective\" \"float fov\" [10]\n")
                           .append(
                               "Film \"image\" \"integer xresolution\" [4] "
                               "\"integer yresolution\" [4]\n")
                           .append(kCentreSampler);
  std::string world =
      std::string("Material \"mirror\" \"rgb Kr\" [0.5 0.5 0.5]\n")
          .append("AreaLightSource \"diffuse\" \"rgb L\" [2 2 2] \"bool twosided\" [\"true\"]\n")
          .append(quad("-100 -100 1  100 -100 1  100 100 1  -100 100 1"))
          .append(quad("-100 -100 -1  100 -100 -1  100 100 -1  -100 100 -1"));
  const double le = 2, refl = 0.5;
  double worst = 0;
  for (int d = 0; d <= 5; ++d) {
    auto r = test::renderSceneText(scene(header, whitted(d), world));
    double expected = le * (1 - std::pow(refl, std::max(d, 1))) / (1 - refl);
    forEachPixel(r.film(), [&](const Point2i& p) {
      Spectrum v = r.film().pixelValue(p);
      for (int c = 0; c < 3; ++c) {
        double err = std::abs(v[c] - expected) / expected;
        worst = std::max(worst, err);
        EXPECT_LT(err, 1e-6) << "maxdepth " << d << " pixel " << p.x << "," << p.y;
      }
    });
  }
  recordError("worst_relative_error", worst);
}

// A glass sphere (index 1.5, Kr = Kt = 1) in front of a uniform sky of radiance 1. Specular
// surfaces take no direct light, so maxdepth 1 leaves the sphere black. Each further depth adds
// non-negative path terms whose Fresnel weights sum to at most 1 (the eta^2 radiance scalings
// of entering and leaving cancel), so every pixel grows with maxdepth and stays <= 1. On the
// axis every interface is met head-on with reflectance F0 = ((eta-1)/(eta+1))^2: maxdepth 2
// sees only the front reflection, F0; d >= 3 adds the light that leaves the sphere after j
// internal reflections, for j <= d-3 (through the far side for even j, back through the front for
// odd j): L = F0 + (1 - F0)^2 sum_{j<d-2} F0^j = F0 + (1 - F0)(1 - F0^(d-2)).
TEST(Whitted, GlassSphereAgainstUniformSky) {
  std::string header = std::string("LookAt 0 0 5  0 0 0  0 1 0\n")
                           .append("Camera \"perspective\" \"float fov\" [30]\n")
                           .append(
                               "Film \"image\" \"integer xresolution\" [9] "
                               "\"integer yresolution\" [9]\n")
                           .append(kCentreSampler);
  std::string world =
      "LightSource \"infinite\" \"rgb L\" [1 1 1]\n"
      "Material \"glass\" \"float index\" [1.5]\n"
      "Shape \"sphere\" \"float radius\" [1]\n";
  const double f0 = 0.04;
  std::vector<std::vector<Float>> byDepth;  // [depth-1][pixel], green channel
  int spherePixels = 0;
  double worstAxis = 0;
  for (int d = 1; d <= 5; ++d) {
    auto r = test::renderSceneText(scene(header, whitted(d), world));
    const Film& film = r.film();
    std::vector<Float> values;
    spherePixels = 0;
    forEachPixel(film, [&](const Point2i& p) {
      Spectrum v = film.pixelValue(p);
      values.push_back(v[1]);
      EXPECT_EQ(v[0], v[1]);
      EXPECT_EQ(v[2], v[1]);
      if (film.pixelAlpha(p) == 0) {
        EXPECT_EQ(v[1], 1.f) << "the sky, seen directly";
        return;
      }
      ++spherePixels;
      EXPECT_LE(v[1], 1 + 1e-6) << "energy, maxdepth " << d;
      if (d == 1)
        EXPECT_EQ(v[1], 0.f) << "unlit specular surface";
      else
        EXPECT_GT(v[1], 0.f) << "the front reflection, maxdepth " << d;
    });
    double axis = film.pixelValue(Point2i(4, 4))[1];
    double expected = d == 1 ? 0 : d == 2 ? f0 : f0 + (1 - f0) * (1 - std::pow(f0, d - 2));
    worstAxis = std::max(worstAxis, std::abs(axis - expected));
    EXPECT_NEAR(axis, expected, 1e-5) << "maxdepth " << d;
    byDepth.push_back(values);
  }
  EXPECT_GT(spherePixels, 9);
  EXPECT_LT(spherePixels, 81);
  for (size_t d = 1; d < byDepth.size(); ++d)
    for (size_t i = 0; i < byDepth[d].size(); ++i)
      EXPECT_GE(byDepth[d][i], byDepth[d - 1][i]) << "maxdepth " << d + 1 << " pixel " << i;
  recordError("worst_axis_error", worstAxis);
}

TEST(Whitted, MaxDepthOutOfRangeIsASceneErrorAtTheParameter) {
  // Negative, or so deep that the recursion would overflow a thread's stack (two facing mirrors
  // crashed past 10,000 levels); the path integrator loops instead, and takes any depth.
  for (const char* integrator : {"whitted", "directlighting", "path"})
    for (const char* depth : {"-1", "1001"}) {
      std::string text = std::string(
                             "Film \"image\" \"integer xresolution\" [2] \"integer yresolution\" "
                             "[2]\nCamera \"perspective\"\nSurfaceIntegrator \"")
                             .append(integrator)
                             .append("\"\n  \"integer maxdepth\" [")
                             .append(depth)
                             .append("]\nWorldBegin\nWorldEnd\n");
      bool accepted = std::string(integrator) == "path" && std::string(depth) == "1001";
      try {
        test::buildSceneText(text);
        EXPECT_TRUE(accepted) << integrator << " " << depth;
      } catch (const SceneError& e) {
        EXPECT_FALSE(accepted) << e.what();
        EXPECT_EQ(e.location().line, 4) << e.what();
      }
    }
}

// A plane mirror reflects the camera's offset rays exactly: the specular differentials must give
// the mirror images of the incoming offset rays, started where they meet the mirror.
TEST(Whitted, PlaneMirrorDifferentialsAreTheMirroredOffsetRays) {
  SurfaceInteraction si(Point3f(0, 0, 0), Vector3f(), Point2f(0.5f, 0.5f), Vector3f(),
                        Vector3f(1, 0, 0), Vector3f(0, 1, 0), Normal3f(), Normal3f(), 0, false);
  RayDifferential ray(Point3f(-1, 0.5f, 2), normalize(Vector3f(1, -0.5f, -2)));
  ray.hasDifferentials = true;
  ray.rxOrigin = ray.o;
  ray.ryOrigin = ray.o;
  ray.rxDirection = normalize(Vector3f(1.01f, -0.5f, -2));
  ray.ryDirection = normalize(Vector3f(1, -0.49f, -2));
  si.wo = -ray.d;
  si.computeDifferentials(ray);
  BSDF bsdf(si);
  Vector3f wi(ray.d.x, ray.d.y, -ray.d.z);
  RayDifferential out = spawnSpecularRay(si, bsdf, ray, wi, false);
  ASSERT_TRUE(out.hasDifferentials);
  for (const auto& [origin, dir, outOrigin, outDir] :
       {std::tuple(ray.rxOrigin, ray.rxDirection, out.rxOrigin, out.rxDirection),
        std::tuple(ray.ryOrigin, ray.ryDirection, out.ryOrigin, out.ryDirection)}) {
    Float t = -origin.z / dir.z;
    Point3f hit = origin + dir * t;
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(outOrigin[i], hit[i], 1e-5f);
    Vector3f mirrored(dir.x, dir.y, -dir.z);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(outDir[i], mirrored[i], 1e-5f);
  }
}

// Snell's law for a unit direction d meeting a surface of normal n (either side) with index
// ratio eta = eta_incident / eta_transmitted.
Vector3f refractDirection(const Vector3f& d, Vector3f n, Float eta) {
  if (dot(d, n) > 0) n = -n;
  Float cosI = -dot(d, n);
  Float cosT = std::sqrt(1 - eta * eta * (1 - cosI * cosI));
  return d * eta + n * (eta * cosI - cosT);
}

// Refraction is not linear, so the differentials are a first-order prediction: through a flat
// interface (index 1.5) the offset rays' refracted directions must agree with Snell's law to
// second order in the offset (|offset| ~ 5e-3, so within 2e-4), entering and leaving the glass.
TEST(Whitted, RefractedDifferentialsFollowSnellToFirstOrder) {
  for (Float side : {1.f, -1.f}) {
    RayDifferential ray(Point3f(-1, 0.5f, 2 * side), normalize(Vector3f(1, -0.5f, -2 * side)));
    ray.hasDifferentials = true;
    ray.rxOrigin = ray.ryOrigin = ray.o;
    ray.rxDirection = normalize(Vector3f(1.01f, -0.5f, -2 * side));
    ray.ryDirection = normalize(Vector3f(1, -0.49f, -2 * side));
    SurfaceInteraction si(Point3f(0, 0, 0), Vector3f(), Point2f(0.5f, 0.5f), -ray.d,
                          Vector3f(1, 0, 0), Vector3f(0, 1, 0), Normal3f(), Normal3f(), 0, false);
    si.computeDifferentials(ray);
    BSDF bsdf(si, 1.5f);
    Float eta = side > 0 ? 1 / 1.5f : 1.5f;
    Vector3f n(0, 0, 1);
    Vector3f wi = refractDirection(ray.d, n, eta);
    RayDifferential out = spawnSpecularRay(si, bsdf, ray, wi, true);
    ASSERT_TRUE(out.hasDifferentials);
    for (const auto& [offset, outDir] : {std::pair(ray.rxDirection, out.rxDirection),
                                         std::pair(ray.ryDirection, out.ryDirection)}) {
      Vector3f exact = refractDirection(offset, n, eta);
      EXPECT_GT((exact - wi).length(), 1e-3f) << "the offset must be visible";
      EXPECT_LT((outDir - exact).length(), 2e-4f) << "side " << side;
    }
  }
}

// --- ambientocclusion ---

std::string aoHeader(const std::string& lookAt, const std::string& camera, int res,
                     int pixelSamples) {
  std::string n = std::to_string(res);
  return std::string("LookAt ")
      .append(lookAt)
      .append("\nCamera ")
      .append(camera)
      .append("\nFilm \"image\" \"integer xresolution\" [")
      .append(n)
      .append("] \"integer yresolution\" [")
      .append(n)
      .append("]\nSampler \"random\" \"integer pixelsamples\" [")
      .append(std::to_string(pixelSamples))
      .append("]\n");
}

std::string ao(int nSamples, const std::string& extra = "",
               const std::string& name = "ambientocclusion") {
  return std::string("\"")
      .append(name)
      .append("\" \"integer nsamples\" [")
      .append(std::to_string(nSamples))
      .append("] ")
      .append(extra);
}

const std::string kFloor = quad("-1000 -1000 0  1000 -1000 0  1000 1000 0  -1000 1000 0");

TEST(AmbientOcclusion, OpenPlaneIsExactlyOne) {
  auto r = test::renderSceneText(scene(
      aoHeader("0 0 3  0 0 0  0 1 0", "\"perspective\" \"float fov\" [60]", 8, 4), ao(64), kFloor));
  forEachPixel(r.film(), [&](const Point2i& p) {
    EXPECT_EQ(r.film().pixelAlpha(p), 1.f);
    Spectrum v = r.film().pixelValue(p);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(v[c], 1.f) << p.x << "," << p.y;
  });
}

// AO at the floor point a distance h in front of a wall of height H (the plane x = 0, endless
// along y), seen by a one-pixel orthographic camera straight above it.
Float aoInFrontOfWall(Float h, Float wallHeight, int nSamples, int pixelSamples,
                      const std::string& extra = "", const std::string& name = "ambientocclusion") {
  std::string x = std::to_string(-h);
  std::string header =
      aoHeader(std::string(x).append(" 0 5  ").append(x).append(" 0 0  0 1 0"),
               "\"orthographic\" \"float screenwindow\" [-1e-4 1e-4 -1e-4 1e-4]", 1, pixelSamples);
  std::string top = std::to_string(wallHeight);
  std::string wall = quad(
      std::string("0 -10000 0  0 10000 0  0 10000 ").append(top).append("  0 -10000 ").append(top));
  auto r = test::renderSceneText(scene(header, ao(nSamples, extra, name), kFloor + wall));
  return r.film().pixelValue(Point2i(0, 0))[1];
}

// Binomial standard deviation of a fraction p estimated from n independent directions; the
// stratified directions do better, so 4 of these is a loose bound.
double binomialSigma(double p, double n) { return std::sqrt(std::max(p * (1 - p), 1e-12) / n); }

// Cosine-weighted directions project to points (a, b) uniform on the unit disk (Malley), with
// a = w_x toward the wall. A direction hits the wall iff a > 0 and the height where it meets
// x = h, h w_z / a, is at most H; with k = H / h that is (1 + k^2) a^2 + b^2 >= 1, the part of
// the half disk a > 0 outside an ellipse of semi-axes 1/sqrt(1+k^2) and 1. Blocked fraction:
// (pi/2 - pi/(2 sqrt(1+k^2))) / pi = (1 - h / sqrt(h^2 + H^2)) / 2.
TEST(AmbientOcclusion, WallOfFiniteHeightMatchesClosedForm) {
  const int nSamples = 4096, pixelSamples = 16;
  const double n = double(nSamples) * pixelSamples, wallHeight = 1;
  double worstSigmas = 0, worstAbs = 0;
  for (double h : {0.25, 0.5, 1.0, 2.0, 4.0}) {
    double expected = 1 - 0.5 * (1 - h / std::sqrt(h * h + wallHeight * wallHeight));
    double got = aoInFrontOfWall(Float(h), Float(wallHeight), nSamples, pixelSamples);
    double sigma = binomialSigma(expected, n);
    worstSigmas = std::max(worstSigmas, std::abs(got - expected) / sigma);
    worstAbs = std::max(worstAbs, std::abs(got - expected));
    EXPECT_NEAR(got, expected, 4 * sigma) << "h = " << h;
  }
  recordError("worst_error_in_sigmas", worstSigmas);
  recordError("worst_absolute_error", worstAbs);
}

// With probes of length d and a wall taller than d, a direction is blocked iff it reaches x = h
// within d: a >= h / d. The disk's segment beyond the chord a = c has area acos(c) - c sqrt(1-c^2).
// A wall farther away than maxdist blocks nothing.
TEST(AmbientOcclusion, MaxDistCutsTheProbes) {
  const int nSamples = 4096, pixelSamples = 16;
  const double n = double(nSamples) * pixelSamples;
  EXPECT_EQ(aoInFrontOfWall(2, 1000, 256, 4, "\"float maxdist\" [1.9]"), 1.f);
  double c = 0.5;  // h = 1, maxdist = 2
  double expected = 1 - (std::acos(c) - c * std::sqrt(1 - c * c)) / kPi;
  double got = aoInFrontOfWall(1, 1000, nSamples, pixelSamples, "\"float maxdist\" [2]");
  double sigma = binomialSigma(expected, n);
  EXPECT_NEAR(got, expected, 4 * sigma);
  recordError("segment_absolute_error", std::abs(got - expected));
  recordError("segment_error_in_sigmas", std::abs(got - expected) / sigma);
  // Unbounded probes see the whole wall: half of all directions when it is endless.
  double half = aoInFrontOfWall(1, 1e5f, nSamples, pixelSamples);
  EXPECT_NEAR(half, 0.5, 4 * binomialSigma(0.5, n));
  recordError("endless_wall_absolute_error", std::abs(half - 0.5));
}

// pbrt-v2's uniform directions ("bool cossample" false): an endless wall at distance h within
// maxdist blocks the directions with w_x > c = h / maxdist, a cap of the sphere whose upper half
// is (1 - c) / 2 of the hemisphere, so (1 + c) / 2 stay clear (0.75 at c = 0.5, where the
// cosine-weighted value is 0.8045).
TEST(AmbientOcclusion, UniformDirectionsArePbrtV2s) {
  const int nSamples = 4096, pixelSamples = 16;
  const double n = double(nSamples) * pixelSamples, c = 0.5, expected = (1 + c) / 2;
  double got = aoInFrontOfWall(1, 1e5f, nSamples, pixelSamples,
                               "\"float maxdist\" [2] \"bool cossample\" \"false\"");
  EXPECT_NEAR(got, expected, 4 * binomialSigma(expected, n));
  double half = aoInFrontOfWall(1, 1e5f, nSamples, pixelSamples, "\"bool cossample\" \"false\"");
  EXPECT_NEAR(half, 0.5, 4 * binomialSigma(0.5, n));
}

// pbrt-v3's "ao": the integral of cos over the clear directions, pi times the cosine-weighted
// clear fraction, whichever way the directions are drawn. Open: exactly pi with cosine-weighted
// directions (each clear one adds cos / pdf = pi).
TEST(AmbientOcclusionPbrtV3, OpenPlaneIsExactlyPi) {
  auto r = test::renderSceneText(
      scene(aoHeader("0 0 3  0 0 0  0 1 0", "\"perspective\" \"float fov\" [60]", 8, 4),
            ao(64, "", "ao"), kFloor));
  forEachPixel(r.film(), [&](const Point2i& p) {
    Spectrum v = r.film().pixelValue(p);
    for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(v[c], kPi) << p.x << "," << p.y;
  });
}

// In front of the wall of the closed form above: pi (1 - (1 - h / sqrt(h^2 + H^2)) / 2). With
// uniform directions each sample is 2 pi cos or 0, of variance at most E[(2 pi cos)^2] = 4 pi^2 /
// 3; cosine-weighted ones are pi times a binomial fraction.
TEST(AmbientOcclusionPbrtV3, WallIsPiTimesTheCosineWeightedClearFraction) {
  const int nSamples = 4096, pixelSamples = 16;
  const double n = double(nSamples) * pixelSamples, h = 0.5, wallHeight = 1;
  double fraction = 1 - 0.5 * (1 - h / std::sqrt(h * h + wallHeight * wallHeight));
  double cosine = aoInFrontOfWall(Float(h), Float(wallHeight), nSamples, pixelSamples, "", "ao");
  EXPECT_NEAR(cosine, kPi * fraction, 4 * kPi * binomialSigma(fraction, n));
  double uniform = aoInFrontOfWall(Float(h), Float(wallHeight), nSamples, pixelSamples,
                                   "\"bool cossample\" \"false\"", "ao");
  EXPECT_NEAR(uniform, kPi * fraction, 4 * std::sqrt(4 * kPi * kPi / 3 / n));
  // Not the clear fraction of uniform directions, which pbrt-v2's integrator would give.
  double uniformFraction = aoInFrontOfWall(Float(h), Float(wallHeight), nSamples, pixelSamples,
                                           "\"bool cossample\" \"false\"");
  EXPECT_GT(std::abs(uniform - kPi * uniformFraction), 0.05);
}

TEST(AmbientOcclusionPbrtV3, NonPositiveSampleCountIsASceneError) {
  try {
    test::buildSceneText("Integrator \"ao\"\n  \"integer nsamples\" [-2]\nWorldBegin\nWorldEnd\n");
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.location().line, 2) << e.what();
  }
}

TEST(AmbientOcclusion, ClosedBoxAroundTheCameraIsBlack) {
  std::string header = aoHeader("0 0 0  0 0 1  0 1 0", "\"perspective\" \"float fov\" [90]", 8, 2);
  std::string cube =
      "Shape \"trianglemesh\" \"point P\" [-1 -1 -1  1 -1 -1  1 1 -1  -1 1 -1  "
      "-1 -1 1  1 -1 1  1 1 1  -1 1 1]\n"
      "  \"integer indices\" [0 1 2 0 2 3  4 6 5 4 7 6  0 4 5 0 5 1  3 2 6 3 6 7  "
      "0 3 7 0 7 4  1 5 6 1 6 2]\n";
  for (const std::string& world : {cube, std::string("Shape \"sphere\" \"float radius\" [2]\n")}) {
    auto r = test::renderSceneText(scene(header, ao(256), world));
    forEachPixel(r.film(), [&](const Point2i& p) {
      EXPECT_EQ(r.film().pixelAlpha(p), 1.f);
      EXPECT_EQ(r.film().pixelValue(p)[1], 0.f) << p.x << "," << p.y;
    });
  }
}

TEST(AmbientOcclusion, EscapingRaysAreZeroAndTransparent) {
  auto r = test::renderSceneText(scene(aoHeader("0 0 3  0 0 0  0 1 0", "\"perspective\"", 4, 1),
                                       ao(16), "Shape \"sphere\" \"float radius\" [0.01]\n"));
  Point2i corner(0, 0);
  EXPECT_EQ(r.film().pixelAlpha(corner), 0.f);
  EXPECT_EQ(r.film().pixelValue(corner)[1], 0.f);
}

TEST(AmbientOcclusion, SameBitsForAnyThreadCountAndTileSize) {
  std::string text = scene(
      aoHeader("-3 -2 2  0 0 0.5  0 0 1", "\"perspective\" \"float fov\" [50]", 16, 4), ao(32),
      kFloor + quad("0 -10000 0  0 10000 0  0 10000 1  0 -10000 1") +
          "Shape \"sphere\" \"float radius\" [0.5]\n");
  test::TestRenderOptions one, two;
  one.render = RenderOptions{1, 16, true};
  two.render = RenderOptions{2, 3, true};
  auto a = test::renderSceneText(text, one);
  auto b = test::renderSceneText(text, two);
  int grey = 0;
  forEachPixel(a.film(), [&](const Point2i& p) {
    Spectrum va = a.film().pixelValue(p), vb = b.film().pixelValue(p);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(va[c], vb[c]) << p.x << "," << p.y;
    if (va[1] > 0 && va[1] < 1) ++grey;
  });
  EXPECT_GT(grey, 16) << "the scene should have partly occluded pixels";
}

TEST(AmbientOcclusion, BadParametersAreSceneErrorsAndTheNamesAreKnown) {
  for (const char* bad : {"\"integer nsamples\" [0]", "\"float maxdist\" [0]"}) {
    std::string text =
        std::string("Camera \"perspective\"\nSurfaceIntegrator \"ambientocclusion\"\n  ")
            .append(bad)
            .append("\nWorldBegin\nWorldEnd\n");
    try {
      test::buildSceneText(text);
      ADD_FAILURE() << "no error for " << bad;
    } catch (const SceneError& e) {
      EXPECT_EQ(e.location().line, 3) << e.what();
    }
  }
  try {
    test::buildSceneText("SurfaceIntegrator \"nosuchintegrator\"\nWorldBegin\nWorldEnd\n");
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    std::string what = e.what();
    EXPECT_NE(what.find("whitted"), std::string::npos) << what;
    EXPECT_NE(what.find("ambientocclusion"), std::string::npos) << what;
    EXPECT_NE(what.find("photonmap"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace candela
