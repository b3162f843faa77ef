// pbrt-v3's Trowbridge-Reitz distribution (pbrt 3e §8.4.2-8.4.3): normalisation over projected
// area, Smith's Lambda against the projected-area identity, G1 and G bounds, the roughness remap
// against its formula, and the visible-normal density integrating to 1.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "core/rng.h"
#include "reflection/trowbridge_reitz.h"

namespace candela {
namespace {

Vector3f dir(double thetaDeg, double phiDeg) {
  double t = thetaDeg * M_PI / 180, p = phiDeg * M_PI / 180;
  return Vector3f(Float(std::sin(t) * std::cos(p)), Float(std::sin(t) * std::sin(p)),
                  Float(std::cos(t)));
}

// Integral of g over the upper hemisphere by the midpoint rule in (psi, phi) with
// tan theta = a tan psi: a lobe of width a in tan theta is spread over the whole psi range.
double hemisphereIntegral(const std::function<double(const Vector3f&)>& g, double a,
                          int nPsi = 1000, int nPhi = 1024) {
  double sum = 0, dPsi = (M_PI / 2) / nPsi, dPhi = 2 * M_PI / nPhi;
  for (int i = 0; i < nPsi; ++i) {
    double psi = (i + 0.5) * dPsi, t = std::tan(psi);
    double theta = std::atan(a * t);
    // dtheta / dpsi = a sec^2 psi / (1 + a^2 tan^2 psi).
    double jacobian = a * (1 + t * t) / (1 + a * a * t * t) * std::sin(theta);
    double s = std::sin(theta), c = std::cos(theta);
    for (int j = 0; j < nPhi; ++j) {
      double phi = (j + 0.5) * dPhi;
      Vector3f w(Float(s * std::cos(phi)), Float(s * std::sin(phi)), Float(c));
      sum += g(w) * jacobian * dPsi * dPhi;
    }
  }
  return sum;
}

const std::pair<Float, Float> kAlphas[] = {{0.01f, 0.01f}, {0.1f, 0.1f}, {0.5f, 0.5f},
                                           {1, 1},         {0.1f, 0.5f}, {0.6f, 0.06f}};

TEST(TrowbridgeReitz, DIsNormalisedOverProjectedArea) {
  for (auto [ax, ay] : kAlphas) {
    TrowbridgeReitzDistribution d(ax, ay);
    double integral = hemisphereIntegral([&](const Vector3f& w) { return double(d.d(w)) * w.z; },
                                         std::sqrt(ax * ay));
    EXPECT_NEAR(integral, 1, 1e-3) << ax << " " << ay;
  }
}

TEST(TrowbridgeReitz, DHandComputed) {
  // Isotropic alpha = 0.5 at theta_h = 30 degrees: tan^2 = 1/3, cos^4 = 9/16,
  // D = 1 / (pi 0.25 (9/16) (1 + (1/3) / 0.25)^2) = 1 / (pi 0.140625 (7/3)^2) = 0.4157517.
  TrowbridgeReitzDistribution iso(0.5f, 0.5f);
  EXPECT_NEAR(iso.d(dir(30, 70)), 0.4157517f, 1e-5f);
  EXPECT_NEAR(iso.d(-dir(30, 70)), 0.4157517f, 1e-5f);  // symmetric about the surface
  EXPECT_NEAR(iso.d(Vector3f(0, 0, 1)), 1 / (kPi * 0.25f), 1e-5f);
  // Anisotropic: along x the bracket holds only alpha_x, along y only alpha_y, and the prefactor
  // 1 / (ax ay) sets the ratio to the isotropic distributions: 0.25 / 0.05 and 0.01 / 0.05.
  TrowbridgeReitzDistribution aniso(0.5f, 0.1f), isoY(0.1f, 0.1f);
  EXPECT_NEAR(aniso.d(dir(30, 0)), iso.d(dir(30, 0)) * 5, 1e-5f);
  Float alongY = isoY.d(dir(30, 90)) * 0.2f;
  EXPECT_NEAR(aniso.d(dir(30, 90)), alongY, 1e-5f * alongY);
}

TEST(TrowbridgeReitz, LambdaSatisfiesTheProjectedAreaIdentity) {
  // The projected area of the visible microfacets equals that of the macrosurface:
  // integral of G1(wo) max(0, wo . wh) D(wh) dwh = cos theta_o. This ties Lambda to D.
  for (auto [ax, ay] : kAlphas)
    for (double theta : {0.0, 60.0, 89.0})
      for (double phi : {0.0, 35.0}) {
        TrowbridgeReitzDistribution d(ax, ay);
        Vector3f wo = dir(theta, phi);
        double lhs = hemisphereIntegral(
            [&](const Vector3f& wh) {
              return double(d.g1(wo)) * std::max(0.0, double(dot(wo, wh))) * d.d(wh);
            },
            std::sqrt(ax * ay), 500, 512);
        EXPECT_NEAR(lhs, wo.z, 2e-3) << ax << " " << ay << " theta " << theta << " phi " << phi;
      }
}

TEST(TrowbridgeReitz, VisibleNormalDensityIntegratesToOne) {
  for (auto [ax, ay] : kAlphas)
    for (double theta : {0.0, 45.0, 85.0, 130.0}) {
      TrowbridgeReitzDistribution d(ax, ay);
      Vector3f wo = dir(theta, 20);
      // pdf takes wh on either side; the hemisphere above covers each microfacet once.
      double integral =
          hemisphereIntegral([&](const Vector3f& wh) { return d.pdf(wo, wh); }, std::sqrt(ax * ay));
      EXPECT_NEAR(integral, 1, 2e-3) << ax << " " << ay << " theta " << theta;
    }
}

TEST(TrowbridgeReitz, MaskingBoundsAndLimits) {
  RNG rng(5);
  for (auto [ax, ay] : kAlphas) {
    TrowbridgeReitzDistribution d(ax, ay);
    EXPECT_EQ(d.g1(Vector3f(0, 0, 1)), 1);  // nothing is hidden seen from straight above
    EXPECT_EQ(d.g1(Vector3f(1, 0, 0)), 0);  // everything is at the horizon
    for (int i = 0; i < 1000; ++i) {
      Vector3f a = dir(89.99 * rng.uniformFloat(), 360 * rng.uniformFloat());
      Vector3f b = dir(89.99 * rng.uniformFloat(), 360 * rng.uniformFloat());
      Float g1a = d.g1(a), g1b = d.g1(b), g = d.g(a, b);
      ASSERT_GE(g1a, 0);
      ASSERT_LE(g1a, 1);
      ASSERT_EQ(d.g1(-a), g1a);  // symmetric about the surface
      // Correlated heights: at least the product of the independent terms, at most either.
      ASSERT_LE(g, std::min(g1a, g1b) * (1 + 1e-6f));
      ASSERT_GE(g, g1a * g1b * (1 - 1e-6f));
    }
  }
  // Lambda for alpha = 0.5 at 60 degrees: alpha^2 tan^2 = 0.75, (sqrt(1.75) - 1) / 2.
  TrowbridgeReitzDistribution iso(0.5f, 0.5f);
  EXPECT_NEAR(iso.lambda(dir(60, 10)), (std::sqrt(1.75) - 1) / 2, 1e-6);
  // Rougher surfaces hide more.
  TrowbridgeReitzDistribution rough(1, 1);
  EXPECT_LT(rough.g1(dir(70, 0)), iso.g1(dir(70, 0)));
}

TEST(TrowbridgeReitz, RoughnessRemapFollowsThePolynomialInLogRoughness) {
  auto formula = [](double r) {
    double x = std::log(std::max(r, 1e-3));
    return 1.62142 + 0.819955 * x + 0.1734 * x * x + 0.0171201 * x * x * x +
           0.000640711 * x * x * x * x;
  };
  for (double r : {1e-3, 0.01, 0.05, 0.1, 0.3, 0.5, 1.0})
    EXPECT_NEAR(roughnessToAlpha(Float(r)), formula(r), 1e-5 * formula(r)) << r;
  EXPECT_NEAR(roughnessToAlpha(1), 1.62142f, 1e-6f);  // x = 0: the constant term
  // Below 1e-3 the roughness is clamped.
  EXPECT_EQ(roughnessToAlpha(1e-5f), roughnessToAlpha(1e-3f));
  EXPECT_EQ(roughnessToAlpha(0), roughnessToAlpha(1e-3f));
  // Monotonic over the range the formula is meant for.
  for (double r = 2e-3; r <= 1; r *= 1.5)
    EXPECT_GT(roughnessToAlpha(Float(r)), roughnessToAlpha(Float(r / 1.5))) << r;
}

TEST(TrowbridgeReitz, SampledNormalsFaceWoAndZeroAlphaIsClamped) {
  RNG rng(11);
  TrowbridgeReitzDistribution d(0.3f, 0.05f);
  for (Vector3f wo : {dir(0, 0), dir(60, 30), dir(89.9, 200), dir(120, 45), dir(179, 10)})
    for (int i = 0; i < 2000; ++i) {
      Vector3f wh = d.sampleWh(wo, Point2f(rng.uniformFloat(), rng.uniformFloat()));
      ASSERT_NEAR(wh.length(), 1, 1e-5);
      ASSERT_GE(wh.z * wo.z, 0);  // on wo's side
      ASSERT_GE(dot(wo, wh), -1e-6f);
      ASSERT_TRUE(std::isfinite(d.pdf(wo, wh)));
    }
  TrowbridgeReitzDistribution zero(0, 0);
  EXPECT_EQ(zero.alphaX(), TrowbridgeReitzDistribution::kMinAlpha);
  EXPECT_TRUE(std::isfinite(zero.d(Vector3f(0, 0, 1))));
}

}  // namespace
}  // namespace candela
