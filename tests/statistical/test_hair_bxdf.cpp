// The hair BxDF by Monte Carlo, with fixed seeds:
// - white furnace (after pbrt-v3's own hair tests): without absorption or tilt, the integral of
//   f |cos theta_i| over the sphere, averaged over h, is 1 for beta_m, beta_n in 0.1 .. 1, by
//   uniform sampling with a z-test on the sample's standard error; with absorption it is below 1;
// - importance sampling: sampleF's pdf and value are pdf() and f() at its direction, its
//   directions follow pdf() (chi-square over a 20 x 40 histogram, 1M samples per case, including
//   tilted, narrow and nearly axial cases), and without absorption or tilt every weight
//   f |cos| / pdf is 1, so that the sampled furnace is 1 with no variance.
// Significance: 0.01 for each family of tests, Sidak-corrected per case.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "core/sampling.h"
#include "direction_stats.h"
#include "reflection/hair_absorption.h"
#include "reflection/hair_bxdf.h"

namespace candela {
namespace {

constexpr double kFamilyAlpha = 0.01;

struct Estimate {
  double mean = 0, standardError = 0;
};

// The integral of S = f |cos theta_i| over the sphere for one wo, averaged over h uniform in
// [-1, 1], from n uniform directions.
Estimate uniformFurnace(const Spectrum& sigmaA, Float betaM, Float betaN, Float alpha,
                        uint64_t seed, int n) {
  RNG rng(seed);
  Vector3f wo = sampleUniformSphere({rng.uniformFloat(), rng.uniformFloat()});
  double sum = 0, sum2 = 0;
  for (int i = 0; i < n; ++i) {
    Float h = -1 + 2 * rng.uniformFloat();
    HairBxDF b(h, 1.55f, sigmaA, betaM, betaN, alpha);
    Vector3f wi = sampleUniformSphere({rng.uniformFloat(), rng.uniformFloat()});
    double x = b.f(wo, wi).y() * std::abs(wi.z) / uniformSpherePdf();
    sum += x;
    sum2 += x * x;
  }
  Estimate e;
  e.mean = sum / n;
  e.standardError = std::sqrt(std::max(0.0, sum2 / n - e.mean * e.mean) / (n - 1));
  return e;
}

TEST(HairFurnace, LosslessFibreReflectsEverything) {
  const Float betas[] = {0.1f, 0.3f, 0.5f, 0.7f, 0.9f, 1.0f};
  const int cases = 36;
  double alpha = stats::sidak(kFamilyAlpha, cases);
  uint64_t seed = 1;
  for (Float betaM : betas)
    for (Float betaN : betas) {
      Estimate e = uniformFurnace(Spectrum(0), betaM, betaN, 0, seed++, 300000);
      double p = stats::normalTwoSidedTail((e.mean - 1) / e.standardError);
      EXPECT_GT(p, alpha) << "beta_m " << betaM << " beta_n " << betaN << ": " << e.mean << " +- "
                          << e.standardError;
      if (getenv("CANDELA_VERBOSE_STATS"))
        std::cout << "furnace beta_m " << betaM << " beta_n " << betaN << ": " << e.mean << " +- "
                  << e.standardError << "\n";
    }
}

TEST(HairFurnace, AbsorbingFibreReflectsLess) {
  // One-sided: the mean lies below 1 by more than z(0.01 / 3) standard errors. Without tilt, so
  // that only absorption can take energy away.
  const Spectrum absorbing[] = {hair::sigmaAFromConcentration(1.3f, 0),
                                hair::sigmaAFromConcentration(0, 0.3f),
                                hair::sigmaAFromReflectance(Spectrum(0.2f), 0.3f)};
  uint64_t seed = 100;
  for (const Spectrum& sigmaA : absorbing) {
    Estimate e = uniformFurnace(sigmaA, 0.3f, 0.3f, 0, seed++, 300000);
    EXPECT_LT(e.mean + 2.94 * e.standardError, 1) << e.mean << " +- " << e.standardError;
  }
}

struct SamplingCase {
  const char* name;
  Float h, betaM, betaN, alpha;
  Spectrum sigmaA;
  Vector3f wo;
};

Vector3f unit(Float x, Float y, Float z) { return normalize(Vector3f(x, y, z)); }

std::vector<SamplingCase> samplingCases() {
  Spectrum brown = hair::sigmaAFromConcentration(1.3f, 0);
  return {
      {"brown_default", 0.3f, 0.3f, 0.3f, 2, brown, unit(0.3f, 0.5f, 0.8f)},
      {"narrow_untilted", -0.7f, 0.1f, 0.1f, 0, Spectrum(0), unit(-0.4f, 0.2f, 0.9f)},
      {"narrow_tilted", 0.5f, 0.1f, 0.1f, 2, Spectrum(0), unit(0.6f, -0.3f, 0.5f)},
      {"rough_coloured", 0.9f, 1, 1, 5, hair::sigmaAFromReflectance(Spectrum(0.5f), 1),
       unit(0.1f, 0.9f, 0.3f)},
      // Nearly along the fibre: the tilted lobes wrap past the poles.
      {"axial", -0.2f, 0.3f, 0.5f, 2, Spectrum(0.2f), unit(0.95f, 0.1f, 0.2f)},
      {"large_tilt", 0, 0.6f, 0.2f, 10, hair::sigmaAFromConcentration(0.2f, 0.8f),
       unit(-0.8f, 0.3f, -0.4f)},
  };
}

class HairSampling : public testing::TestWithParam<int> {};

TEST_P(HairSampling, SamplesFollowPdf) {
  std::vector<SamplingCase> cases = samplingCases();
  const SamplingCase& c = cases[size_t(GetParam())];
  HairBxDF b(c.h, 1.55f, c.sigmaA, c.betaM, c.betaN, c.alpha);
  int64_t pdfMismatch = 0, fMismatch = 0;
  stats::DirectionDraw draw = [&](Float, const Point2f& u, Vector3f* wi) {
    Float pdf = 0;
    Spectrum f = b.sampleF(c.wo, wi, u, &pdf);
    if (pdf == 0) return false;
    // The same arithmetic as pdf() and f(): equal but for the last bits.
    if (std::abs(pdf - b.pdf(c.wo, *wi)) > 1e-5f * pdf) ++pdfMismatch;
    Spectrum fe = b.f(c.wo, *wi);
    for (int k = 0; k < 3; ++k)
      if (std::abs(f[k] - fe[k]) > 1e-5f * std::max(f[k], fe[k])) ++fMismatch;
    return true;
  };
  auto pdf = [&](const Vector3f& wi) { return double(b.pdf(c.wo, wi)); };
  stats::FitResult r = stats::chiSquareFit(draw, pdf, 1000000, 11 + uint64_t(GetParam()));
  EXPECT_GT(r.pValue, stats::sidak(kFamilyAlpha, int(cases.size())))
      << c.name << ": " << r.summary();
  EXPECT_EQ(pdfMismatch, 0) << c.name;
  EXPECT_EQ(fMismatch, 0) << c.name;
  // The pdf is a density: it integrates to the fraction of draws that succeed (u below 1e-5 in
  // Mp's sampling is moved up, so all do), within the cubature's 1e-3.
  EXPECT_NEAR(r.pdfIntegral, 1, 1e-3) << c.name << ": " << r.summary();
  if (getenv("CANDELA_VERBOSE_STATS")) std::cout << c.name << ": " << r.summary() << "\n";
}

INSTANTIATE_TEST_SUITE_P(Cases, HairSampling, testing::Range(0, 6));

TEST(HairSampling, LosslessUntiltedWeightsAreOne) {
  // Without absorption the lobes are picked in proportion to Ap, which sums to 1, and without
  // tilt pdf() is S itself: every weight f |cos| / pdf is 1 up to Float rounding, for random wo
  // and h and every roughness.
  RNG rng(5);
  int64_t off = 0, drawn = 0;
  double sum = 0;
  for (Float betaM : {0.1f, 0.4f, 1.0f})
    for (Float betaN : {0.1f, 0.5f, 1.0f})
      for (int i = 0; i < 20000; ++i) {
        HairBxDF b(-1 + 2 * rng.uniformFloat(), 1.55f, Spectrum(0), betaM, betaN, 0);
        Vector3f wo = sampleUniformSphere({rng.uniformFloat(), rng.uniformFloat()}), wi;
        Float pdf;
        Spectrum f = b.sampleF(wo, &wi, {rng.uniformFloat(), rng.uniformFloat()}, &pdf);
        if (pdf == 0) continue;
        double w = f.y() * std::abs(wi.z) / pdf;
        sum += w;
        ++drawn;
        if (std::abs(w - 1) > 1e-4) ++off;
      }
  EXPECT_EQ(off, 0);
  EXPECT_EQ(drawn, 180000);
  EXPECT_NEAR(sum / double(drawn), 1, 1e-5);
}

}  // namespace
}  // namespace candela
