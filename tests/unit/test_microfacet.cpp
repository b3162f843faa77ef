// Microfacet distributions and the Torrance-Sparrow BRDF against hand-computed values (lrt draft
// §9.4; seed notes §25), and the normalisation integral of D cos theta_h.
#include <gtest/gtest.h>

#include "reflection/microfacet.h"

namespace candela {
namespace {

Vector3f dir(Float thetaDeg, Float phiDeg) {
  Float t = radians(thetaDeg), p = radians(phiDeg);
  return Vector3f(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
}

// Integral over the hemisphere of g(w) by the midpoint rule in (cos theta, phi), fine enough for
// the exponents used here (lobes wider than a few hundred cells).
double hemisphereIntegral(const std::function<double(const Vector3f&)>& g, int n = 1000) {
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    // cos theta = 1 - u^2 puts more cells near the pole, where the lobes are.
    double u0 = double(i) / n, u1 = double(i + 1) / n, u = (i + 0.5) / n;
    double c = 1 - u * u, dc = (1 - u0 * u0) - (1 - u1 * u1);
    double s = std::sqrt(std::max(0.0, 1 - c * c));
    for (int j = 0; j < 2 * n / 10; ++j) {
      double phi = 2 * M_PI * (j + 0.5) / (2 * n / 10);
      sum += g(Vector3f(Float(s * std::cos(phi)), Float(s * std::sin(phi)), Float(c))) * dc *
             (2 * M_PI / (2 * n / 10));
    }
  }
  return sum;
}

TEST(Microfacet, BlinnDHandComputed) {
  // D = (e + 2) / (2 pi) cos^e: e = 10 at theta_h = 0 is 12 / (2 pi) = 1.9098593, at 30 degrees
  // 1.9098593 * 0.75^5 = 0.4532186 (cos^2 30 = 0.75).
  BlinnDistribution blinn(10);
  EXPECT_NEAR(blinn.d(Vector3f(0, 0, 1)), 1.9098593f, 1e-6f);
  EXPECT_NEAR(blinn.d(dir(30, 77)), 0.4532186f, 1e-6f);
  EXPECT_NEAR(blinn.d(-dir(30, 77)), 0.4532186f, 1e-6f);  // symmetric about the surface
  // The sampling density is (e + 1) / (2 pi) cos^e: 11 / (2 pi) at the pole.
  EXPECT_NEAR(blinn.pdfWh(Vector3f(0, 0, 1)), 1.7507044f, 1e-6f);
}

TEST(Microfacet, AnisotropicDHandComputed) {
  // ex = 10, ey = 100, theta_h = 20, phi_h = 30 degrees: e = 10 * 0.75 + 100 * 0.25 = 32.5;
  // sqrt(12 * 102) / (2 pi) = 5.5681, cos(20)^32.5 = 0.132445; D = 0.737479.
  AnisotropicDistribution aniso(10, 100);
  EXPECT_NEAR(aniso.d(dir(20, 30)), 0.737479f, 2e-5f);
  // At the pole every exponent gives cos^e = 1 (no 0/0).
  EXPECT_NEAR(aniso.d(Vector3f(0, 0, 1)), std::sqrt(12.f * 102.f) / (2 * kPi), 1e-5f);
  // Along x the exponent is ex: equal exponents reduce to Blinn.
  AnisotropicDistribution iso(25, 25);
  BlinnDistribution blinn(25);
  for (Float t : {0.f, 5.f, 20.f, 60.f})
    EXPECT_NEAR(iso.d(dir(t, 40)), blinn.d(dir(t, 40)), 1e-5f * blinn.d(Vector3f(0, 0, 1)));
}

TEST(Microfacet, DistributionsAreNormalisedOverProjectedArea) {
  // integral of D cos theta_h = 1 (lrt draft eq. 9.4.9), and the sampling densities integrate
  // to 1 over solid angle.
  for (Float e : {0.f, 1.f, 10.f, 100.f}) {
    BlinnDistribution b(e);
    EXPECT_NEAR(hemisphereIntegral([&](const Vector3f& w) { return b.d(w) * w.z; }), 1, 1e-3) << e;
    EXPECT_NEAR(hemisphereIntegral([&](const Vector3f& w) { return b.pdfWh(w); }), 1, 1e-3) << e;
  }
  for (auto [ex, ey] : {std::pair{1.f, 1.f}, {10.f, 100.f}, {100.f, 3.f}, {0.f, 50.f}}) {
    AnisotropicDistribution a(ex, ey);
    EXPECT_NEAR(hemisphereIntegral([&](const Vector3f& w) { return a.d(w) * w.z; }), 1, 1e-3)
        << ex << " " << ey;
    EXPECT_NEAR(hemisphereIntegral([&](const Vector3f& w) { return a.pdfWh(w); }), 1, 1e-3)
        << ex << " " << ey;
  }
}

TEST(Microfacet, VGrooveGHandComputed) {
  // Mirror pair at 60 degrees: wh = n, 2 (n.h)(n.wo) / (wo.h) = 2 > 1, G = 1.
  Vector3f wo = dir(60, 0), wi = dir(60, 180);
  EXPECT_FLOAT_EQ(vGrooveG(wo, wi, normalize(wo + wi)), 1);
  // wo at 80 degrees, wi = n: wh bisects at 40 degrees, n.h = wo.h = cos 40, so
  // G = min(1, 2 cos 80, 2) = 2 cos 80 = 0.3472964.
  wo = dir(80, 0);
  wi = Vector3f(0, 0, 1);
  EXPECT_NEAR(vGrooveG(wo, wi, normalize(wo + wi)), 0.3472964f, 1e-6f);
  EXPECT_NEAR(vGrooveG(wi, wo, normalize(wo + wi)), 0.3472964f, 1e-6f);
}

TEST(Microfacet, TorranceSparrowHandComputed) {
  // Normal incidence and exitance with Blinn e = 10, no Fresnel loss: D = 1.9098593, G = 1,
  // f = D / 4 = 0.4774648.
  BlinnDistribution blinn(10);
  FresnelNoOp noOp;
  MicrofacetReflection m(Spectrum(1), &noOp, &blinn);
  EXPECT_NEAR(m.f(Vector3f(0, 0, 1), Vector3f(0, 0, 1))[0], 0.4774648f, 1e-6f);
  // wo at 80 degrees, wi = n (both at phi 0): D(40) G / (4 cos 80 * 1) with G = 2 cos 80:
  // D(40) / 2 = 1.9098593 * cos(40)^10 / 2 = 1.9098593 * 0.0694... / 2.
  Float d40 = 1.9098593f * std::pow(std::cos(radians(40)), 10.f);
  EXPECT_NEAR(m.f(dir(80, 0), Vector3f(0, 0, 1))[0], d40 / 2, 1e-5f);
  // Reflectance scales it; the Fresnel term multiplies it.
  FresnelDielectric glass(1, 1.5f);
  MicrofacetReflection g(Spectrum(0.5f), &glass, &blinn);
  EXPECT_NEAR(g.f(Vector3f(0, 0, 1), Vector3f(0, 0, 1))[0], 0.5f * 0.04f * 0.4774648f, 1e-7f);
}

TEST(Microfacet, InsideADielectricTotalInternalReflectionRaisesTheFresnelTerm) {
  // Both directions below the surface, at 60 degrees to -n (past glass's critical angle of
  // 41.8): the Fresnel cosine is negative, the exiting case, and F = 1 instead of ~0.09.
  BlinnDistribution blinn(100);
  FresnelDielectric glass(1, 1.5f);
  FresnelNoOp noOp;
  MicrofacetReflection withGlass(Spectrum(1), &glass, &blinn), mirror(Spectrum(1), &noOp, &blinn);
  Vector3f wo = dir(120, 0), wi = dir(120, 180);
  EXPECT_NEAR(withGlass.f(wo, wi)[0], mirror.f(wo, wi)[0], 1e-6f * mirror.f(wo, wi)[0]);
  Vector3f wo2 = dir(60, 0), wi2 = dir(60, 180);
  EXPECT_NEAR(withGlass.f(wo2, wi2)[0] / mirror.f(wo2, wi2)[0], 0.0891867f, 1e-5f);
}

TEST(Microfacet, SamplingRejectsTheOtherHemisphereAndHandlesGrazing) {
  BlinnDistribution blinn(1);
  FresnelNoOp noOp;
  MicrofacetReflection m(Spectrum(1), &noOp, &blinn);
  Vector3f wi;
  Float pdf = 1;
  EXPECT_TRUE(m.sampleF(Vector3f(1, 0, 0), &wi, Point2f(0.3f, 0.3f), &pdf).isBlack());
  EXPECT_EQ(pdf, 0);
  EXPECT_EQ(m.pdf(dir(30, 0), dir(150, 0)), 0);
  EXPECT_TRUE(m.f(Vector3f(0, 0, 1), Vector3f(0, 0, -1)).isBlack());
  EXPECT_EQ(m.type(), BxDFType(kReflection | kGlossy));
}

}  // namespace
}  // namespace candela
