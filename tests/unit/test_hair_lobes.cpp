// The factors of the hair model (reflection/hair_lobes.h) and its absorption parameterisations,
// by deterministic quadrature: Mp and Np are normalised, Mp's two branches and I0's two branches
// agree where they meet, the attenuations of a lossless fibre sum to 1, and the pigment
// conversions give Chiang et al. 2016's coefficients (as pbrt 4e §9.9.8 prints them).
#include <gtest/gtest.h>

#include <cmath>

#include "reflection/hair_absorption.h"
#include "reflection/hair_lobes.h"

namespace candela {
namespace {

// Composite Simpson's rule with n (even) intervals: error ~ h^4 f'''' / 180, far below 1e-7 for
// the lobes here at the n used.
template <typename F>
double simpson(F f, double a, double b, int n) {
  double h = (b - a) / n, s = f(a) + f(b);
  for (int i = 1; i < n; ++i) s += f(a + i * h) * (i % 2 ? 4 : 2);
  return s * h / 3;
}

TEST(HairLobes, BesselI0MatchesKnownValuesAndItsLogBranchesAgree) {
  EXPECT_NEAR(hair::besselI0(0), 1, 1e-15);
  EXPECT_NEAR(hair::besselI0(1), 1.2660658777520082, 1e-14);  // Abramowitz & Stegun table 9.8
  EXPECT_NEAR(hair::besselI0(-2), 2.2795853023360673, 1e-13);
  // Our series (below 30) and asymptotic expansion (from 30) against the standard library's I0,
  // on both sides of the switch and up to where I0 still fits a double; the logarithm too.
  for (double x : {1e-3, 0.5, 3.0, 12.0, 29.999, 30.0, 30.001, 45.0, 100.0, 499.0, 501.0, 700.0}) {
    const double reference = std::cyl_bessel_i(0.0, x);
    EXPECT_NEAR(hair::besselI0(x), reference, 1e-14 * reference) << x;
    EXPECT_NEAR(hair::logBesselI0(x), std::log(reference), 1e-14 * std::log(reference)) << x;
  }
  // Beyond a double's range the logarithm stays finite and close to x - log(2 pi x) / 2.
  EXPECT_NEAR(hair::logBesselI0(1e4), 1e4 - 0.5 * std::log(2 * M_PI * 1e4), 1e-4);
}

TEST(HairLobes, LongitudinalIsNormalisedForWideAndNarrowLobes) {
  // v from beta_m = 0.1's TT lobe (1.4e-3, deep in the log-space branch) up to beta_m = 1's TRT
  // (~110); the branch switches at 0.1.
  for (double v : {1.4e-3, 0.01, 0.05, 0.1, 0.1000001, 0.3, 1.0, 5.0, 110.0})
    for (double thetaO : {-1.3, -0.4, 0.0, 0.7, 1.5}) {
      double so = std::sin(thetaO), co = std::cos(thetaO);
      double integral = simpson(
          [&](double t) {
            return hair::longitudinalScattering(std::cos(t), co, std::sin(t), so, v) * std::cos(t);
          },
          -M_PI / 2, M_PI / 2, 50000);
      EXPECT_NEAR(integral, 1, 1e-6) << "v " << v << " theta_o " << thetaO;
    }
}

TEST(HairLobes, LongitudinalBranchesMeetAtTheSwitch) {
  // The direct formula just above v = 0.1 and the log-space one at 0.1 describe the same function.
  double below = hair::longitudinalScattering(0.9, 0.8, -0.3, 0.4, 0.1);
  double above = hair::longitudinalScattering(0.9, 0.8, -0.3, 0.4, std::nextafter(0.1, 1.0));
  EXPECT_NEAR(below / above, 1, 1e-9);
}

TEST(HairLobes, LongitudinalIsSymmetricInItsTwoAngles) {
  for (double v : {0.005, 0.2, 3.0})
    for (double a : {-1.2, -0.3, 0.5})
      for (double b : {-0.8, 0.1, 1.1}) {
        double m1 =
            hair::longitudinalScattering(std::cos(a), std::cos(b), std::sin(a), std::sin(b), v);
        double m2 =
            hair::longitudinalScattering(std::cos(b), std::cos(a), std::sin(b), std::sin(a), v);
        EXPECT_DOUBLE_EQ(m1, m2);
      }
}

TEST(HairLobes, AzimuthalIsNormalisedOverTheCircle) {
  for (Float betaN : {0.1f, 0.3f, 0.6f, 1.0f})
    for (int p = 0; p < hair::kMaxLobe; ++p)
      for (Float h : {-0.95f, -0.3f, 0.0f, 0.8f}) {
        Float gammaO = std::asin(h), gammaT = std::asin(h / 1.7f);
        Float s = hair::azimuthalScale(betaN);
        double integral = simpson(
            [&](double phi) {
              return double(hair::azimuthalScattering(Float(phi), p, s, gammaO, gammaT));
            },
            -M_PI, M_PI, 100000);
        // Float evaluation of a lobe of width s ~ 0.017 at beta_n = 0.1: 1e-5 is its rounding.
        EXPECT_NEAR(integral, 1, 1e-5) << "beta_n " << betaN << " p " << p << " h " << h;
      }
}

TEST(HairLobes, TrimmedLogisticSamplingInvertsItsCdf) {
  for (Float s : {0.02f, 0.3f, 2.0f})
    for (Float u : {0.001f, 0.1f, 0.5f, 0.77f, 0.999f}) {
      Float x = hair::sampleTrimmedLogistic(u, s, -kPi, kPi);
      double cdf =
          simpson([&](double t) { return double(hair::trimmedLogistic(Float(t), s, -kPi, kPi)); },
                  -M_PI, x, 200000);
      EXPECT_NEAR(cdf, u, 2e-5) << "s " << s << " u " << u;
    }
}

TEST(HairLobes, AttenuationOfALosslessFibreSumsToOne) {
  for (Float cosThetaO : {1.0f, 0.7f, 0.2f})
    for (Float h : {-0.99f, -0.5f, 0.0f, 0.3f, 0.9f}) {
      hair::LobeSpectra a = hair::attenuation(cosThetaO, 1.55f, h, Spectrum(1));
      Float sum = 0;
      for (const Spectrum& s : a) sum += s[0];
      EXPECT_NEAR(sum, 1, 1e-6);
      // Absorption takes energy from every lobe but R.
      hair::LobeSpectra b = hair::attenuation(cosThetaO, 1.55f, h, Spectrum(0.5f));
      EXPECT_EQ(b[0][0], a[0][0]);
      for (int p = 1; p <= hair::kMaxLobe; ++p) EXPECT_LT(b[p][0], a[p][0]);
    }
}

TEST(HairAbsorption, MelaninConcentrationsUseThePublishedCoefficients) {
  // Chiang et al. 2016's eumelanin and pheomelanin absorption (pbrt 4e §9.9.8).
  Spectrum eu = hair::sigmaAFromConcentration(1, 0), ph = hair::sigmaAFromConcentration(0, 1);
  EXPECT_FLOAT_EQ(eu[0], 0.419f);
  EXPECT_FLOAT_EQ(eu[1], 0.697f);
  EXPECT_FLOAT_EQ(eu[2], 1.37f);
  EXPECT_FLOAT_EQ(ph[0], 0.187f);
  EXPECT_FLOAT_EQ(ph[1], 0.4f);
  EXPECT_FLOAT_EQ(ph[2], 1.05f);
  // Linear in both: pbrt-v3's default brown is 1.3 eumelanin.
  Spectrum mix = hair::sigmaAFromConcentration(1.3f, 0.5f);
  for (int i = 0; i < 3; ++i) EXPECT_FLOAT_EQ(mix[i], 1.3f * eu[i] + 0.5f * ph[i]);
}

TEST(HairAbsorption, ReflectanceInversionIsChiangsFit) {
  // sqrt(sigma_a) = -ln(c) / D(beta_n): white hair absorbs nothing, darker colours more, and the
  // polynomial D is Chiang et al.'s (eq. 9) at beta_n = 0.3: 5.969 - .0645 + .22788 - .28971 +
  // .0451494 + .00059535.
  double d = 5.969 - 0.215 * 0.3 + 2.532 * 0.09 - 10.73 * 0.027 + 5.574 * 0.0081 + 0.245 * 0.00243;
  Spectrum s = hair::sigmaAFromReflectance(Spectrum(1, 0.5f, 0.1f), 0.3f);
  EXPECT_EQ(s[0], 0);
  EXPECT_NEAR(s[1], std::pow(std::log(0.5) / d, 2), 1e-6);
  EXPECT_NEAR(s[2], std::pow(std::log(0.1) / d, 2), 1e-6);
  Float previous = std::numeric_limits<Float>::infinity();
  for (Float c = 0.05f; c <= 1; c += 0.05f) {
    Float sigma = hair::sigmaAFromReflectance(Spectrum(c), 0.6f)[0];
    EXPECT_LT(sigma, previous) << c;
    previous = sigma;
  }
}

}  // namespace
}  // namespace candela
