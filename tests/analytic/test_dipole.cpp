// The dipole diffusion BSSRDF (Jensen et al. 2001; pbrt 2e §16.5): the profile Rd(r) integrates
// over the plane to the closed-form total diffuse reflectance, and the kdsubsurface inversion of
// that closed form round-trips.
#include <gtest/gtest.h>

#include <cmath>

#include "reflection/dipole.h"

namespace candela {
namespace {

// The integral of Rd(r) 2 pi r dr over [0, inf) for one channel, by the midpoint rule in t with
// r = L t / (1 - t) (L the profile's longer length scale), in double.
double integratedProfile(const DipoleProfile& profile, int channel, double L) {
  constexpr int kSteps = 400000;
  double sum = 0;
  for (int i = 0; i < kSteps; ++i) {
    double t = (i + 0.5) / kSteps;
    double r = L * t / (1 - t);
    double drdt = L / ((1 - t) * (1 - t));
    sum += double(profile.Rd(Float(r * r))[channel]) * 2 * 3.14159265358979323846 * r * drdt;
  }
  return sum / kSteps;
}

struct Medium {
  Spectrum sigmaA, sigmaPrimeS;
  Float eta;
};

TEST(Dipole, ProfileIntegratesToTheClosedFormTotalReflectance) {
  // Whole milk, skin, ketchup (mm^-1, Jensen et al. 2001), a strongly absorbing medium, a nearly
  // non-absorbing one, and eta = 1 (no boundary reflection).
  const Medium media[] = {{{0.0011f, 0.0024f, 0.014f}, {2.55f, 3.21f, 3.77f}, 1.33f},
                          {{0.032f, 0.17f, 0.48f}, {0.74f, 0.88f, 1.01f}, 1.3f},
                          {{0.061f, 0.97f, 1.45f}, {0.18f, 0.07f, 0.03f}, 1.3f},
                          {{5.0f, 2.0f, 1.0f}, {1.0f, 1.0f, 1.0f}, 1.5f},
                          {{1e-4f, 1e-3f, 1e-2f}, {10.0f, 10.0f, 10.0f}, 1.0f}};
  for (const Medium& m : media) {
    DipoleProfile profile({m.sigmaA, m.sigmaPrimeS, m.eta});
    Spectrum closed = profile.totalReflectance();
    for (int c = 0; c < 3; ++c) {
      SCOPED_TRACE(::testing::Message() << "sigma_a " << m.sigmaA[c] << " sigma_s' "
                                        << m.sigmaPrimeS[c] << " eta " << m.eta);
      double sigmaPrimeT = m.sigmaA[c] + m.sigmaPrimeS[c];
      double sigmaTr = std::sqrt(3 * m.sigmaA[c] * sigmaPrimeT);
      double L = std::max(1 / sigmaPrimeT, 1 / sigmaTr);
      double numeric = integratedProfile(profile, c, L);
      // The closed form written out here as well, so a wrong A or albedo in both fails.
      double albedo = m.sigmaPrimeS[c] / sigmaPrimeT;
      double fdr = -1.440 / (m.eta * m.eta) + 0.710 / m.eta + 0.668 + 0.0636 * m.eta;
      double A = (1 + fdr) / (1 - fdr);
      double s = std::sqrt(3 * (1 - albedo));
      double expected = albedo / 2 * (1 + std::exp(-4.0 / 3 * A * s)) * std::exp(-s);
      EXPECT_NEAR(closed[c], expected, 1e-5 * expected + 1e-7);
      // The quadrature and Float evaluation of Rd are good to about 1e-4 relative.
      EXPECT_NEAR(numeric, expected, 5e-4 * expected) << "numeric " << numeric;
    }
  }
}

TEST(Dipole, BoundaryTermFromTheFresnelFit) {
  // Fdr at eta = 1.3: -1.44/1.69 + 0.71/1.3 + 0.668 + 0.0636 * 1.3 = 0.44476.
  EXPECT_NEAR(diffuseFresnelReflectance(1.3f), 0.44476, 1e-4);
  EXPECT_NEAR(dipoleBoundaryA(1.3f), 1.44476 / 0.55524, 1e-3);
  // No boundary, almost no internal reflection.
  EXPECT_NEAR(diffuseFresnelReflectance(1.0f), 0.0016, 1e-4);
}

TEST(Dipole, KdInversionRoundTrips) {
  for (Float eta : {1.0f, 1.33f, 1.5f}) {
    Float A = dipoleBoundaryA(eta);
    Float previous = 2;
    for (int i = 1; i <= 99; ++i) {
      Float kd = Float(i) / 100;
      Float absorbed = absorbedFractionForDiffuseReflectance(kd, A);
      EXPECT_GE(absorbed, 0);
      EXPECT_LE(absorbed, 1);
      EXPECT_LT(absorbed, previous);  // monotone: more reflection, less absorption
      previous = absorbed;
      EXPECT_NEAR(totalDiffuseReflectanceOfAbsorption(absorbed, A), kd, 1e-6) << "eta " << eta;
      // The albedo form agrees where 1 - a' is representable well.
      if (kd <= 0.9f) {
        EXPECT_NEAR(totalDiffuseReflectance(1 - absorbed, A), kd, 1e-5);
      }
    }
    // Through the material's parameterisation: coefficients whose dipole reflects Kd, with
    // sigma_t' = 1 / meanfreepath.
    Spectrum kd(0.01f, 0.5f, 0.99f);
    for (Float mfp : {0.1f, 1.0f, 7.0f}) {
      BSSRDFCoefficients c = coefficientsFromDiffuse(kd, mfp, eta);
      Spectrum total = DipoleProfile(c).totalReflectance();
      for (int ch = 0; ch < 3; ++ch) {
        EXPECT_NEAR(total[ch], kd[ch], 2e-6);
        EXPECT_NEAR(c.sigmaA[ch] + c.sigmaPrimeS[ch], 1 / mfp, 1e-5 / mfp);
      }
    }
  }
}

}  // namespace
}  // namespace candela
