// Fresnel reflectance against closed forms (lrt draft §9.2; seed notes §25).
#include <gtest/gtest.h>

#include "reflection/fresnel.h"

namespace candela {
namespace {

TEST(Fresnel, DielectricNormalIncidenceIsSquaredIndexContrast) {
  // ((eta - 1) / (eta + 1))^2: 0.04 for glass.
  EXPECT_NEAR(fresnelDielectric(1, 1, 1.5f), 0.04f, 1e-6f);
  EXPECT_NEAR(fresnelDielectric(-1, 1, 1.5f), 0.04f, 1e-6f);  // the same from inside
  for (Float eta : {1.0001f, 1.333f, 2.42f, 10.f}) {
    Float r = (eta - 1) / (eta + 1);
    EXPECT_NEAR(fresnelDielectric(1, 1, eta), r * r, 1e-6f) << eta;
    EXPECT_NEAR(FresnelDielectric(1, eta).evaluate(1)[0], r * r, 1e-6f) << eta;
  }
  EXPECT_NEAR(fresnelDielectric(0.3f, 1.5f, 1.5f), 0, 1e-12f);  // no interface, no reflection
}

TEST(Fresnel, BrewsterAngleReflectsOnlyThePerpendicularPolarisation) {
  // At tan(theta) = eta, r_par = 0 and r_perp = (1 - eta^2) / (1 + eta^2): for eta = 1.5,
  // r_perp = -5/13 and F = (25/169) / 2 = 25/338 = 0.0739645.
  Float theta = std::atan(1.5f);
  EXPECT_NEAR(fresnelDielectric(std::cos(theta), 1, 1.5f), 25.f / 338.f, 2e-6f);
  Float cosT = std::cos(std::asin(std::sin(theta) / 1.5f));
  Float par = (1.5f * std::cos(theta) - cosT) / (1.5f * std::cos(theta) + cosT);
  EXPECT_NEAR(par, 0, 1e-6f);
}

TEST(Fresnel, TotalInternalReflectionPastTheCriticalAngle) {
  // From inside glass (eta 1.5) the critical angle is asin(1 / 1.5) = 41.81 degrees.
  Float critical = std::asin(1 / 1.5f);
  for (Float deg : {41.9f, 45.f, 60.f, 89.9f}) {
    Float c = std::cos(radians(deg));
    EXPECT_EQ(fresnelDielectric(-c, 1, 1.5f), 1) << deg;
    EXPECT_EQ(FresnelDielectric(1, 1.5f).evaluate(-c)[0], 1) << deg;
    // Seen from outside at the same angle, most light is transmitted (short of grazing).
    if (deg < 80) {
      EXPECT_LT(fresnelDielectric(c, 1, 1.5f), 0.1f) << deg;
    }
  }
  // Just below the critical angle the reflectance is below 1 and rises towards it.
  Float below = fresnelDielectric(-std::cos(critical - 0.01f), 1, 1.5f);
  Float further = fresnelDielectric(-std::cos(critical - 0.1f), 1, 1.5f);
  EXPECT_LT(below, 1);
  EXPECT_GT(below, further);
  EXPECT_GT(fresnelDielectric(-std::cos(critical - 1e-4f), 1, 1.5f), 0.85f);
  // Grazing incidence from outside reflects everything.
  EXPECT_NEAR(fresnelDielectric(1e-6f, 1, 1.5f), 1, 1e-4f);
}

TEST(Fresnel, FrDielectricIsTheMeanOfBothPolarisations) {
  // Hand-computed at 60 degrees in air onto eta 1.5: cos_t = sqrt(1 - (sin 60 / 1.5)^2)
  // = 0.816497; r_par = (1.5 * 0.5 - 0.816497) / (1.5 * 0.5 + 0.816497) = -0.042449,
  // r_perp = (0.5 - 1.5 * 0.816497) / (0.5 + 1.5 * 0.816497) = -0.420204;
  // F = (0.0018019 + 0.1765714) / 2 = 0.0891867.
  EXPECT_NEAR(frDielectric(0.5f, 0.816497f, 1, 1.5f), 0.0891867f, 2e-6f);
  EXPECT_NEAR(fresnelDielectric(0.5f, 1, 1.5f), 0.0891867f, 2e-6f);
}

TEST(Fresnel, ConductorWithoutAbsorptionIsTheDielectricAtNormalIncidence) {
  for (Float eta : {1.2f, 1.5f, 3.f}) {
    Float r = (eta - 1) / (eta + 1);
    EXPECT_NEAR(frConductor(1, Spectrum(eta), Spectrum(0))[0], r * r, 1e-6f);
  }
  // Sign of the cosine does not matter for a conductor.
  FresnelConductor gold(Spectrum(conductor::kGold.eta), Spectrum(conductor::kGold.k));
  EXPECT_EQ(gold.evaluate(0.3f), gold.evaluate(-0.3f));
  // Gold at normal incidence: ((0.37 - 1)^2 + 2.82^2) / ((0.37 + 1)^2 + 2.82^2) = 8.3493 / 9.8293
  // = 0.849430.
  EXPECT_NEAR(gold.evaluate(1)[0], 0.849430f, 1e-5f);
  for (Float c : {0.f, 0.1f, 0.5f, 1.f}) {
    Spectrum v = gold.evaluate(c);
    EXPECT_GE(v[0], 0);
    EXPECT_LE(v[0], 1);
  }
}

TEST(Fresnel, ApproximationsRoundTripThroughTheConductorFormula) {
  for (Float r : {0.f, 0.02f, 0.04f, 0.3f, 0.8f, 0.95f}) {
    Spectrum eta = fresnelApproxEta(Spectrum(r));
    EXPECT_NEAR(frConductor(1, eta, Spectrum(0))[0], r, 1e-5f) << r;
    Spectrum k = fresnelApproxK(Spectrum(r));
    EXPECT_NEAR(frConductor(1, Spectrum(1), k)[0], r, 1e-5f) << r;
  }
  // R = 1 is clamped to 0.999: finite results.
  EXPECT_TRUE(std::isfinite(fresnelApproxEta(Spectrum(1))[0]));
  EXPECT_TRUE(std::isfinite(fresnelApproxK(Spectrum(1))[0]));
  EXPECT_NEAR(frConductor(1, fresnelApproxEta(Spectrum(1)), Spectrum(0))[0], 0.999f, 1e-4f);
}

TEST(Fresnel, NoOpReflectsEverything) {
  FresnelNoOp f;
  EXPECT_EQ(f.evaluate(0.2f), Spectrum(1));
  EXPECT_EQ(f.evaluate(-1), Spectrum(1));
}

}  // namespace
}  // namespace candela
