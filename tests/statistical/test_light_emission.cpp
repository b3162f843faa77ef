// Light emission sampling (pbrt 3e §16.1): for every light, the Monte Carlo estimate of its emitted
// power from sampleLe, the mean of Le |cos θ| / (pdfPos pdfDir), equals power(). Each colour
// channel is a Z-test of the sample mean against the closed form (the central limit theorem at
// 40000 samples), family-wise significance 0.01 over all cases and channels with a Šidák
// correction; fixed seeds. A light whose estimator is constant (a point source) has zero variance
// and must match to rounding. Every sample also checks that pdfLe reports the densities sampleLe
// did.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "core/rng.h"
#include "lights/diffuse_area_light.h"
#include "lights/distant_light.h"
#include "lights/goniometric_light.h"
#include "lights/infinite_light.h"
#include "lights/point_light.h"
#include "lights/projection_light.h"
#include "lights/spot_light.h"
#include "shapes/cone.h"
#include "shapes/cylinder.h"
#include "shapes/disk.h"
#include "shapes/hyperboloid.h"
#include "shapes/paraboloid.h"
#include "shapes/sphere.h"
#include "shapes/triangle_mesh.h"
#include "support/tail_probabilities.h"

namespace candela {
namespace {

constexpr int kCases = 17;  // the EmittedPower tests below, for the Šidák correction
constexpr int kSamples = 40000;

void checkPdfsAgree(const Light& light, const Ray& ray, const Normal3f& n, Float pdfPos,
                    Float pdfDir) {
  Float pos = -1, dir = -1;
  light.pdfLe(ray, n, &pos, &dir);
  ASSERT_NEAR(pos, pdfPos, 1e-4f * pdfPos) << "pdfPos";
  ASSERT_NEAR(dir, pdfDir, 1e-3f * pdfDir) << "pdfDir";
}

void checkEmittedPower(const Light& light, uint64_t seed) {
  RNG rng(seed);
  double sum[3] = {0, 0, 0}, sumSq[3] = {0, 0, 0};
  for (int i = 0; i < kSamples; ++i) {
    Point2f uPos(rng.uniformFloat(), rng.uniformFloat());
    Point2f uDir(rng.uniformFloat(), rng.uniformFloat());
    Ray ray;
    Normal3f n;
    Float pdfPos = 0, pdfDir = 0;
    Spectrum Le = light.sampleLe(uPos, uDir, 0, &ray, &n, &pdfPos, &pdfDir);
    if (pdfPos == 0 || pdfDir == 0) {
      ASSERT_TRUE(Le.isBlack()) << "radiance with zero density";
      continue;
    }
    ASSERT_NEAR(ray.d.length(), 1, 1e-5f);
    ASSERT_NO_FATAL_FAILURE(checkPdfsAgree(light, ray, n, pdfPos, pdfDir));
    double w = absDot(n, ray.d) / n.length() / (double(pdfPos) * double(pdfDir));
    for (int c = 0; c < 3; ++c) {
      double v = double(Le[c]) * w;
      sum[c] += v;
      sumSq[c] += v * v;
    }
  }
  Spectrum power = light.power();
  for (int c = 0; c < 3; ++c) {
    double mean = sum[c] / kSamples;
    double var = std::max(0.0, (sumSq[c] - sum[c] * mean) / (kSamples - 1));
    SCOPED_TRACE("channel " + std::to_string(c) + ": mean " + std::to_string(mean) + ", power " +
                 std::to_string(power[c]));
    if (var <= 1e-12 * mean * mean) {
      EXPECT_NEAR(mean, power[c], 1e-5 * power[c]);
      continue;
    }
    double z = (mean - power[c]) / std::sqrt(var / kSamples);
    EXPECT_GT(stats::normalTwoSidedTail(z), stats::sidak(0.01, 3 * kCases)) << "z = " << z;
  }
}

TEST(EmittedPower, Point) {
  PointLight light(translate(Vector3f(1, 2, 3)), Spectrum(1, 2, 3), Point3f(0.5f, 0, 0));
  checkEmittedPower(light, 1);
}

TEST(EmittedPower, Spot) {
  SpotLight light(rotateX(30), Spectrum(3, 2, 1), Point3f(0, 1, 0), Point3f(1, 0, 2), 40, 15);
  checkEmittedPower(light, 2);
}

TEST(EmittedPower, Projection) {
  ProjectionLight light(rotateY(20) * translate(Vector3f(0, 1, 0)), Spectrum(2), 50, nullptr, 1.6f);
  checkEmittedPower(light, 3);
}

TEST(EmittedPower, ProjectionPortrait) {
  ProjectionLight light(rotateZ(70), Spectrum(1, 0.5f, 2), 80, nullptr, 0.5f);
  checkEmittedPower(light, 4);
}

TEST(EmittedPower, GoniometricIsotropic) {
  GoniometricLight light(rotateX(50), Spectrum(2, 1, 1), nullptr);
  checkEmittedPower(light, 5);
}

// A diagram constant along φ in each row, brighter toward one pole: bilinear lookups inside a row
// are exact, and rows are thin, so power()'s cell sum is what the light emits to the test's bound.
TEST(EmittedPower, GoniometricWithDiagram) {
  int w = 8, h = 64;
  std::vector<Spectrum> texels;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) texels.push_back(Spectrum(1 + 3 * Float(j) / h, 1, 0.5f));
  auto image = std::make_shared<const MIPMap<Spectrum>>(w, h, texels, WrapMode::Clamp);
  GoniometricLight light(rotateY(30), Spectrum(1), image);
  checkEmittedPower(light, 6);
}

TEST(EmittedPower, Distant) {
  DistantLight light(rotateZ(10), Spectrum(1, 2, 0.5f), Point3f(1, 1, 1), Point3f(0, 0, 0));
  light.preprocess(Bounds3f(Point3f(-1, -2, 0), Point3f(3, 1, 1)));
  checkEmittedPower(light, 7);
}

TEST(EmittedPower, InfiniteUniform) {
  InfiniteAreaLight light(rotateY(40), Spectrum(0.5f, 1, 2), 1, {});
  light.preprocess(Bounds3f(Point3f(-1, -1, -1), Point3f(2, 1, 4)));
  checkEmittedPower(light, 8);
}

TEST(EmittedPower, InfiniteWithMap) {
  LatLongMap m{32, 16, std::vector<Spectrum>(32 * 16, Spectrum(0.05f, 0.1f, 0.05f))};
  for (int j = 5; j < 8; ++j)
    for (int i = 20; i < 24; ++i) m.texels[size_t(j) * 32 + size_t(i)] = Spectrum(5, 4, 2);
  InfiniteAreaLight light(rotateX(70) * rotateZ(15), Spectrum(1), 1, m);
  light.preprocess(Bounds3f(Point3f(0, 0, 0), Point3f(1, 2, 3)));
  checkEmittedPower(light, 9);
}

TEST(EmittedPower, AreaSphere) {
  SphereShape sphere(translate(Vector3f(0.3f, -0.2f, 2)), false, 0.7f, -0.7f, 0.7f, 360);
  DiffuseAreaLight light(&sphere, Spectrum(1, 2, 3), 1, false);
  checkEmittedPower(light, 10);
}

TEST(EmittedPower, AreaPartialSphereTwoSided) {
  SphereShape sphere(rotateX(20), true, 1.5f, -0.5f, 1.2f, 250);
  DiffuseAreaLight light(&sphere, Spectrum(2, 1, 1), 1, true);
  checkEmittedPower(light, 11);
}

TEST(EmittedPower, AreaDiskAnnulus) {
  DiskShape disk(rotateY(30), false, 0.5f, 1.5f, 0.4f, 300);
  DiffuseAreaLight light(&disk, Spectrum(1), 1, false);
  checkEmittedPower(light, 12);
}

TEST(EmittedPower, AreaCylinder) {
  CylinderShape cyl(scale(2, 2, 1), false, 0.5f, -1, 1, 360);
  DiffuseAreaLight light(&cyl, Spectrum(1, 1, 2), 1, true);
  checkEmittedPower(light, 13);
}

TEST(EmittedPower, AreaCone) {
  ConeShape cone(Transform(), false, 2, 1, 300);
  DiffuseAreaLight light(&cone, Spectrum(3, 1, 1), 1, false);
  checkEmittedPower(light, 14);
}

TEST(EmittedPower, AreaParaboloid) {
  ParaboloidShape para(rotateX(-40), false, 1, 0.2f, 1.5f, 360);
  DiffuseAreaLight light(&para, Spectrum(1), 1, true);
  checkEmittedPower(light, 15);
}

TEST(EmittedPower, AreaHyperboloid) {
  HyperboloidShape hyp(Transform(), false, Point3f(1, 0, -1), Point3f(0.5f, 1, 1), 360);
  DiffuseAreaLight light(&hyp, Spectrum(1, 2, 1), 1, false);
  checkEmittedPower(light, 16);
}

TEST(EmittedPower, AreaTriangle) {
  TriangleMesh mesh(rotateZ(15), false, {0, 1, 2},
                    {{-1, -0.5f, 1}, {1.5f, -0.3f, 0.8f}, {0, 1, 1.4f}});
  std::vector<std::unique_ptr<Shape>> tris = createTriangleShapes(&mesh);
  DiffuseAreaLight light(tris[0].get(), Spectrum(1, 0.5f, 0.25f), 1, true);
  checkEmittedPower(light, 17);
}

}  // namespace
}  // namespace candela
