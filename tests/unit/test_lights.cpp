// Lights (lrt draft ch. 13; inventory §16, §24, §25): closed-form incident radiance and
// irradiance, the falloff shapes, the draft's sign/aspect defects fixed, and power() against
// the integral of the intensity over the sphere.
#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.h"
#include "lights/diffuse_area_light.h"
#include "lights/distant_light.h"
#include "lights/goniometric_light.h"
#include "lights/infinite_light.h"
#include "lights/point_light.h"
#include "lights/projection_light.h"
#include "lights/spot_light.h"
#include "shapes/disk.h"
#include "shapes/sphere.h"

namespace candela {
namespace {

Interaction at(const Point3f& p) { return Interaction(p, 0); }

// Incident radiance of a delta light at p (already I / r²) and the direction toward it.
Spectrum deltaLi(const Light& light, const Point3f& p, Vector3f* wi) {
  Float pdf;
  VisibilityTester vis;
  Spectrum L = light.sampleLi(at(p), Point2f(0.5f, 0.5f), wi, &pdf, &vis);
  EXPECT_EQ(pdf, 1);
  return L;
}

// Monte Carlo irradiance at p with normal n through the light's sampleLi: mean of L cos / pdf.
double irradiance(const Light& light, const Point3f& p, const Vector3f& n, int samples,
                  uint64_t seed) {
  RNG rng(seed);
  double sum = 0;
  for (int i = 0; i < samples; ++i) {
    Vector3f wi;
    Float pdf;
    VisibilityTester vis;
    Spectrum L =
        light.sampleLi(at(p), Point2f(rng.uniformFloat(), rng.uniformFloat()), &wi, &pdf, &vis);
    if (pdf > 0) sum += double(L[1]) * std::max(0.0, double(dot(wi, n))) / pdf;
  }
  return sum / samples;
}

// ∫ f over the sphere, midpoint rule in (cos θ, φ) about the light-space axis `axis`-agnostic:
// f takes a unit world direction.
template <typename F>
double sphereIntegral(F f, int nCos, int nPhi) {
  double sum = 0;
  for (int i = 0; i < nCos; ++i) {
    double z = -1 + 2 * (i + 0.5) / nCos, r = std::sqrt(1 - z * z);
    for (int j = 0; j < nPhi; ++j) {
      double phi = 2 * M_PI * (j + 0.5) / nPhi;
      sum += f(Vector3f(Float(r * std::cos(phi)), Float(r * std::sin(phi)), Float(z)));
    }
  }
  return sum * (2.0 / nCos) * (2 * M_PI / nPhi);
}

TEST(PointLight, IntensityOverDistanceSquaredIsExact) {
  PointLight light(translate(Vector3f(1, 2, 3)), Spectrum(2, 3, 4), Point3f(0, 0, 1));
  Vector3f wi;
  Spectrum L = deltaLi(light, Point3f(1, 2, 0), &wi);  // distance 4 from (1, 2, 4)
  EXPECT_EQ(L, Spectrum(2, 3, 4) / 16);
  EXPECT_EQ(wi, Vector3f(0, 0, 1));
  EXPECT_FLOAT_EQ(light.power()[0], 4 * kPi * 2);
}

TEST(SpotLight, CentreOutsideAndFalloff) {
  // Aimed along +x from (1, 0, 0): coneangle 30, delta 10, so full intensity within 20 degrees.
  SpotLight light(Transform(), Spectrum(5), Point3f(1, 0, 0), Point3f(3, 0, 0), 30, 10);
  Vector3f wi;
  EXPECT_FLOAT_EQ(deltaLi(light, Point3f(3, 0, 0), &wi)[0], 5.f / 4);  // on the axis, r = 2
  EXPECT_EQ(wi, Vector3f(-1, 0, 0));
  // Behind the light: the draft's sign error would light this point fully.
  EXPECT_EQ(deltaLi(light, Point3f(-1, 0, 0), &wi)[0], 0.f);
  // 40 degrees off the axis: outside the cone.
  Float a = radians(40);
  EXPECT_EQ(deltaLi(light, Point3f(1 + std::cos(a), std::sin(a), 0), &wi)[0], 0.f);
  // 15 degrees off the axis (inside the inner cone) and 25 (in the falloff band), at r = 1.
  a = radians(15);
  EXPECT_FLOAT_EQ(deltaLi(light, Point3f(1 + std::cos(a), 0, std::sin(a)), &wi)[0], 5.f);
  a = radians(25);
  double cosW = std::cos(radians(30)), cosF = std::cos(radians(20));
  double delta = (std::cos(a) - cosW) / (cosF - cosW);
  EXPECT_NEAR(deltaLi(light, Point3f(1 + std::cos(a), 0, std::sin(a)), &wi)[0],
              5 * std::pow(delta, 4), 1e-5);
}

TEST(SpotLight, PowerIsTheIntegralOfTheIntensity) {
  SpotLight light(rotateY(30), Spectrum(2), Point3f(0, 0, 0), Point3f(0, 1, 1), 30, 5);
  double integral =
      2 * sphereIntegral([&](const Vector3f& w) { return double(light.falloff(w)); }, 4000, 400);
  EXPECT_NEAR(light.power()[0], integral, 2e-3 * integral);
  // pbrt-v2's 2πI(1 - (cosF + cosW)/2) treats the δ⁴ band as linear; it is not the integral.
  double cosW = std::cos(radians(30)), cosF = std::cos(radians(25));
  double pbrtApprox = 2 * 2 * M_PI * (1 - (cosF + cosW) / 2);
  EXPECT_GT(std::abs(pbrtApprox - integral), 5e-3 * integral);
}

TEST(DistantLight, ArrivesFromFromTowardToWithIrradianceLCosTheta) {
  // Light travelling along -z (from (0,0,5) to the origin), then the world rotated 90° about x.
  DistantLight light(rotateX(90), Spectrum(3), Point3f(0, 0, 5), Point3f(0, 0, 0));
  Vector3f wi;
  Spectrum L = deltaLi(light, Point3f(0, 0, 0), &wi);
  EXPECT_EQ(L, Spectrum(3));
  EXPECT_NEAR(wi.x, 0, 1e-6);
  EXPECT_NEAR(wi.y, -1, 1e-6);  // rotateX(90) takes +z to -y
  EXPECT_NEAR(wi.z, 0, 1e-6);
  // E = L cos θ on a surface tilted 60 degrees from the light.
  Vector3f n(0, -std::cos(radians(60)), std::sin(radians(60)));
  EXPECT_NEAR(L[0] * dot(wi, n), 1.5, 1e-5);
  light.preprocess(Bounds3f(Point3f(-1, -1, -1), Point3f(1, 1, 1)));
  EXPECT_NEAR(light.power()[0], 3 * kPi * 3, 1e-4);  // R² = 3
}

TEST(ProjectionLight, WindowAspectAndDirection) {
  // No image: a 2:1 window, fov 60 across the shorter side (y), projector looking along +z.
  Float aspect = 2;
  ProjectionLight light(Transform(), Spectrum(4), 60, nullptr, aspect);
  Float t = std::tan(radians(30));
  Vector3f wi;
  EXPECT_FLOAT_EQ(deltaLi(light, Point3f(0, 0, 2), &wi)[0], 1.f);
  EXPECT_EQ(deltaLi(light, Point3f(0, 0, -2), &wi)[0], 0.f);  // behind: the draft's sign error
  // x up to 2 t z is inside (aspect 2, not the integer 2/1 = 2 here but see the portrait case),
  // y beyond t z is outside.
  EXPECT_GT(deltaLi(light, Point3f(1.9f * t, 0, 1), &wi)[0], 0.f);
  EXPECT_EQ(deltaLi(light, Point3f(2.1f * t, 0, 1), &wi)[0], 0.f);
  EXPECT_EQ(deltaLi(light, Point3f(0, 1.1f * t, 1), &wi)[0], 0.f);
  // Portrait 1:2: an integer division would give aspect 0; here y reaches 2 t.
  ProjectionLight portrait(Transform(), Spectrum(4), 60, nullptr, Float(1) / 2);
  EXPECT_GT(deltaLi(portrait, Point3f(0, 1.9f * t, 1), &wi)[0], 0.f);
  EXPECT_EQ(deltaLi(portrait, Point3f(1.1f * t, 0, 1), &wi)[0], 0.f);
}

TEST(ProjectionLight, ImageTopRowTowardMinusYAndPowerIsTheIntegral) {
  // 2 x 2 image, top row 1 and bottom 0, left column red: as in pbrt-v2/v3 the top row leaves
  // toward light-space -y (the slide upside down for a camera at the projector with +y up), and
  // the left column toward -x.
  auto image = std::make_shared<MIPMap<Spectrum>>(
      2, 2, std::vector<Spectrum>{Spectrum(1, 0, 0), Spectrum(0, 0, 1), Spectrum(0), Spectrum(0)},
      WrapMode::Clamp);
  ProjectionLight light(Transform(), Spectrum(1), 45, image, 1);
  Float t = std::tan(radians(22.5f));
  EXPECT_GT(light.projection(Vector3f(-0.9f * t, -0.9f * t, 1))[0], 0.9f);
  EXPECT_LT(light.projection(Vector3f(-0.9f * t, -0.9f * t, 1))[2], 0.1f);
  EXPECT_GT(light.projection(Vector3f(0.9f * t, -0.9f * t, 1))[2], 0.9f);
  EXPECT_LT(light.projection(Vector3f(0, 0.9f * t, 1)).maxComponent(), 0.1f);
  ProjectionLight plain(rotateZ(20), Spectrum(3), 50, nullptr, 1.5f);
  double integral =
      3 *
      sphereIntegral([&](const Vector3f& w) { return double(plain.projection(w)[0]); }, 4000, 1600);
  EXPECT_NEAR(plain.power()[0], integral, 2e-3 * integral);
}

TEST(GoniometricLight, YUpDiagramAndPower) {
  // 2 x 2 image: top row (θ near light-space +y) bright, bottom dark.
  std::vector<Spectrum> texels{Spectrum(2), Spectrum(2), Spectrum(0), Spectrum(0)};
  auto image = std::make_shared<MIPMap<Spectrum>>(2, 2, texels, WrapMode::Clamp);
  GoniometricLight light(Transform(), Spectrum(1), image);
  EXPECT_FLOAT_EQ(light.scale(Vector3f(0, 1, 0))[0], 2.f);
  EXPECT_FLOAT_EQ(light.scale(Vector3f(0, -1, 0))[0], 0.f);
  // Power: the bright hemisphere, 2 × 2π.
  EXPECT_NEAR(light.power()[0], 4 * kPi, 1e-4);
  GoniometricLight constant(Transform(), Spectrum(3),
                            std::make_shared<MIPMap<Spectrum>>(
                                4, 3, std::vector<Spectrum>(12, Spectrum(0.5f)), WrapMode::Clamp));
  EXPECT_NEAR(constant.power()[0], 4 * kPi * 1.5, 1e-4);
  Vector3f wi;
  EXPECT_FLOAT_EQ(deltaLi(constant, Point3f(0, 0, 2), &wi)[0], 1.5f / 4);
}

TEST(InfiniteLight, UniformSkyIrradianceIsPiL) {
  InfiniteAreaLight light(rotateX(30), Spectrum(2), 1, {});
  double E = irradiance(light, Point3f(0, 0, 0), Vector3f(0, 0, 1), 400000, 7);
  EXPECT_NEAR(E, kPi * 2, 0.01 * kPi * 2);
  light.preprocess(Bounds3f(Point3f(0, 0, 0), Point3f(2, 0, 0)));  // R = 1
  EXPECT_NEAR(light.power()[0], 4 * kPi * kPi * 2, 1e-3);
  LatLongMap grey{4, 2, std::vector<Spectrum>(8, Spectrum(0.5f))};
  InfiniteAreaLight mapped(Transform(), Spectrum(2), 1, grey);
  mapped.preprocess(Bounds3f(Point3f(0, 0, 0), Point3f(2, 0, 0)));
  EXPECT_NEAR(mapped.power()[0], 4 * kPi * kPi, 1e-3);
  EXPECT_NEAR(irradiance(mapped, Point3f(0, 0, 0), Vector3f(0, 0, 1), 400000, 8), kPi, 0.01 * kPi);
}

TEST(DiffuseAreaLight, UnitDiskAtDistanceOneGivesHalfPi) {
  DiskShape disk(Transform(), false, 0, 1, 0, 360);
  DiffuseAreaLight light(&disk, Spectrum(1), 1, false);
  // The disk's normal is +z: lit from above, dark from below when one-sided.
  double E = irradiance(light, Point3f(0, 0, 1), Vector3f(0, 0, -1), 400000, 11);
  EXPECT_NEAR(E, kPi / 2, 0.01 * kPi / 2);
  EXPECT_EQ(irradiance(light, Point3f(0, 0, -1), Vector3f(0, 0, 1), 1000, 12), 0.0);
  DiffuseAreaLight twoSided(&disk, Spectrum(1), 1, true);
  EXPECT_NEAR(irradiance(twoSided, Point3f(0, 0, -1), Vector3f(0, 0, 1), 400000, 13), kPi / 2,
              0.01 * kPi / 2);
  EXPECT_NEAR(light.power()[0], kPi * kPi, 1e-4);
  EXPECT_NEAR(twoSided.power()[0], 2 * kPi * kPi, 1e-4);
}

TEST(DiffuseAreaLight, SphereThroughConeSamplingGivesPiLROverDSquared) {
  // Sphere of radius 0.5 and radiance 3 seen from distance 2: E = π L (r / d)² at normal incidence.
  SphereShape sphere(translate(Vector3f(0, 0, 2)), false, 0.5f, -0.5f, 0.5f, 360);
  DiffuseAreaLight light(&sphere, Spectrum(3), 4, false);
  EXPECT_EQ(light.nSamples(), 4);
  double E = irradiance(light, Point3f(0, 0, 0), Vector3f(0, 0, 1), 200000, 17);
  EXPECT_NEAR(E, kPi * 3 / 16, 0.01 * kPi * 3 / 16);
  // Every sample lies in the cone subtended by the sphere, sin θmax = r / d.
  RNG rng(3);
  Float cosMax = std::sqrt(1 - Float(1) / 16);
  for (int i = 0; i < 1000; ++i) {
    Vector3f wi;
    Float pdf;
    VisibilityTester vis;
    light.sampleLi(at(Point3f(0, 0, 0)), Point2f(rng.uniformFloat(), rng.uniformFloat()), &wi, &pdf,
                   &vis);
    ASSERT_GE(wi.z, cosMax - 1e-5f);
    ASSERT_NEAR(pdf, 1 / (2 * kPi * (1 - cosMax)), 1e-2);
  }
  EXPECT_NEAR(light.power()[0], kPi * 3 * 4 * kPi * 0.25, 1e-3);
}

}  // namespace
}  // namespace candela
