// pbrt-v3's Trowbridge-Reitz BxDFs (pbrt 3e §8.4.4): a white furnace (reflectance at most 1 and,
// at normal incidence, at most what the distribution's tails leave above the horizon), a lossless
// rough dielectric reflecting plus transmitting at most the incident power, and reciprocity (for
// transmission, up to the radiance scaling). Integrals by deterministic adaptive quadrature.
#include <gtest/gtest.h>

#include "bxdf_cases.h"
#include "direction_stats.h"

namespace candela {
namespace {

using testcases::direction;

// integral of f(wo, wi) |cos theta_i| over wi in [theta0, theta1] (all azimuths).
double albedo(const BxDF& b, const Vector3f& wo, double theta0, double theta1, double weight = 1) {
  return stats::integrateSphere(
      [&](const Vector3f& wi) { return weight * double(b.f(wo, wi)[0]) * std::abs(wi.z); }, 10, 20,
      theta0, theta1, 1e-5, 1e-7);
}

TEST(TrowbridgeReitzProperties, WhiteFurnaceReflectsAtMostEverything) {
  const std::pair<Float, Float> alphas[] = {
      {0.01f, 0.01f}, {0.1f, 0.1f}, {0.5f, 0.5f}, {1, 1}, {0.05f, 0.5f}};
  FresnelNoOp white;
  for (auto [ax, ay] : alphas)
    for (double theta : {0.0, 30.0, 60.0, 85.0, 89.9}) {
      TrowbridgeReitzDistribution d(ax, ay);
      TrowbridgeReitzReflection r(Spectrum(1), &white, &d);
      double rho = albedo(r, direction(theta, 20), 0, M_PI / 2);
      // 1e-4: the quadrature's tolerance, far below any physical excess.
      EXPECT_LE(rho, 1 + 1e-4) << ax << " " << ay << " theta " << theta;
      // Seen from the normal, microfacets tilted past 45 degrees reflect below the horizon: the
      // fraction with tan^2 theta_h > 1 is alpha^2 / (1 + alpha^2) for this D (its tails are
      // long), and masking of wi only removes more. For smooth surfaces that masking is slight.
      if (theta == 0 && ax == ay) {
        double bound = 1 / (1 + double(ax) * ax);
        EXPECT_LE(rho, bound + 1e-4) << ax;
        if (ax <= 0.1f) {
          EXPECT_GT(rho, 0.99 * bound) << ax;
        }
      }
      EXPECT_GT(rho, 0.3) << ax << " " << ay << " theta " << theta;
    }
}

TEST(TrowbridgeReitzProperties, RoughDielectricConservesEnergy) {
  // Power fractions: reflected albedo plus transmitted albedo times (eta_i / eta_o)^2, the
  // factor that undoes the radiance scaling (as for the specular interface).
  for (Float eta : {1.33f, 1.5f, 2.42f})
    for (Float alpha : {0.05f, 0.3f})
      for (double theta : {0.0, 40.0, 70.0, 110.0, 140.0, 175.0}) {
        TrowbridgeReitzDistribution d(alpha, alpha);
        FresnelDielectric fresnel(1, eta);
        TrowbridgeReitzReflection r(Spectrum(1), &fresnel, &d);
        TrowbridgeReitzTransmission t(Spectrum(1), &d, 1, eta);
        Vector3f wo = direction(theta, 10);
        bool above = wo.z > 0;
        Float etaRatio = above ? eta : 1 / eta;  // eta_i / eta_o
        double reflected = above ? albedo(r, wo, 0, M_PI / 2) : albedo(r, wo, M_PI / 2, M_PI);
        double transmitted = above ? albedo(t, wo, M_PI / 2, M_PI, etaRatio * etaRatio)
                                   : albedo(t, wo, 0, M_PI / 2, etaRatio * etaRatio);
        double total = reflected + transmitted;
        EXPECT_LE(total, 1 + 1e-3) << eta << " " << alpha << " theta " << theta;
        // A smooth interface away from grazing and total internal reflection keeps nearly all.
        if (alpha <= 0.05f && (theta <= 40 || theta >= 175)) {
          EXPECT_GT(total, 0.97) << eta << " " << alpha << " theta " << theta;
        }
        EXPECT_GT(transmitted, 0) << eta << " " << alpha << " theta " << theta;
      }
}

TEST(TrowbridgeReitzProperties, ReciprocalUpToTheRadianceScaling) {
  RNG rng(21);
  TrowbridgeReitzDistribution d(0.3f, 0.08f);
  FresnelConductor gold(Spectrum(0.37f), Spectrum(2.82f));
  FresnelDielectric glass(1, 1.5f);
  TrowbridgeReitzReflection conductor(Spectrum(1), &gold, &d), dielectric(Spectrum(1), &glass, &d);
  TrowbridgeReitzFresnelBlend coat(Spectrum(0.5f), Spectrum(0.1f), &d);
  TrowbridgeReitzTransmission refraction(Spectrum(1), &d, 1, 1.5f);
  double worst = 0, worstT = 0;
  int transmitting = 0;
  for (int i = 0; i < 4000; ++i) {
    Vector3f a = direction(89.5 * rng.uniformFloat(), 360 * rng.uniformFloat());
    Vector3f b = direction(89.5 * rng.uniformFloat(), 360 * rng.uniformFloat());
    for (const BxDF* bx : {static_cast<const BxDF*>(&conductor), static_cast<const BxDF*>(&coat),
                           static_cast<const BxDF*>(&dielectric)}) {
      for (Float side : {1.f, -1.f}) {
        Vector3f p(a.x, a.y, side * a.z), q(b.x, b.y, side * b.z);
        double fab = bx->f(p, q)[0], fba = bx->f(q, p)[0];
        double scale = std::max(fab, fba);
        if (scale > 0) worst = std::max(worst, std::abs(fab - fba) / scale);
      }
    }
    // Transmission from a (above, index 1) to b (below, index 1.5): f(a, b) eta^2 = f(b, a)
    // with eta = 1.5 / 1.
    Vector3f below(b.x, b.y, -b.z);
    double fab = refraction.f(a, below)[0], fba = refraction.f(below, a)[0];
    if (fab > 0 || fba > 0) {
      ++transmitting;
      worstT = std::max(worstT, std::abs(fab * 1.5 * 1.5 - fba) / std::max(fab * 2.25, fba));
    }
  }
  // Float rounding only.
  EXPECT_LT(worst, 1e-4);
  EXPECT_LT(worstT, 1e-3);
  EXPECT_GT(transmitting, 1000);  // the check above ran on many pairs
}

}  // namespace
}  // namespace candela
