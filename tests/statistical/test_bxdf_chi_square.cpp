// Every sampled BxDF draws directions where its pdf says it does (pbrt-v4 / Mitsuba style):
// 1M samples per case into a 20 x 40 (theta, phi) histogram plus a cell for failed samples,
// expected counts from the pdf integrated over each cell by adaptive cubature, cells expected
// below 5 pooled, significance 0.01 for the whole suite (Sidak-corrected per case). Fixed seeds.
// Along the way: sampleF's pdf and value are pdf() and f() at the sampled direction, and the pdf
// integrates to the fraction of samples that succeed (1 for BxDFs that never fail) within 1%.
#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>

#include "bxdf_cases.h"
#include "direction_stats.h"

namespace candela {
namespace {

using testcases::BxDFCase;

constexpr double kSuiteAlpha = 0.01;
constexpr int64_t kSamples = 1000000;

const std::vector<BxDFCase>& normalCases() {
  static const std::vector<BxDFCase> cases = testcases::sampledCases(false);
  return cases;
}
const std::vector<BxDFCase>& sweepCases() {
  static const std::vector<BxDFCase> cases = testcases::sampledCases(true);
  return cases;
}

bool close(double a, double b, double rel) {
  return std::abs(a - b) <= rel * std::max(std::abs(a), std::abs(b)) + 1e-30;
}

void checkCase(const BxDFCase& c, int casesInSuite, uint64_t seed) {
  const BxDF& b = *c.bxdf;
  int64_t pdfMismatch = 0, fMismatch = 0, drawn = 0;
  stats::DirectionDraw draw = [&](Float, const Point2f& u, Vector3f* wi) {
    Float pdf = 0;
    Spectrum f = b.sampleF(c.wo, wi, u, &pdf);
    if (pdf == 0) return false;
    // Every 8th sample is checked: 125k checks, at an eighth of the cost of measured BRDFs'
    // lookups.
    if (drawn++ % 8 != 0) return true;
    // Float rounding of the two code paths: a relative 1e-3 is far above it.
    if (!close(pdf, b.pdf(c.wo, *wi), 1e-3)) ++pdfMismatch;
    Spectrum fe = b.f(c.wo, *wi);
    for (int k = 0; k < 3; ++k)
      if (!close(f[k], fe[k], 1e-3)) ++fMismatch;
    return true;
  };
  auto pdf = [&](const Vector3f& wi) { return double(b.pdf(c.wo, wi)); };
  stats::FitResult r = stats::chiSquareFit(draw, pdf, kSamples, seed);
  double alpha = stats::sidak(kSuiteAlpha, casesInSuite);
  EXPECT_GT(r.pValue, alpha) << c.name << ": " << r.summary();
  EXPECT_EQ(pdfMismatch, 0) << c.name << ": sampleF's pdf differs from pdf()";
  EXPECT_EQ(fMismatch, 0) << c.name << ": sampleF's value differs from f()";
  double successRate = 1 - double(r.failed) / double(r.samples);
  EXPECT_NEAR(r.pdfIntegral, successRate, 0.01) << c.name << ": " << r.summary();
  EXPECT_LE(r.pdfIntegral, 1.01) << c.name;
  if (getenv("CANDELA_VERBOSE_STATS")) std::cout << c.name << ": " << r.summary() << "\n";
}

std::string caseName(const std::string& s) {
  std::string out;
  for (char ch : s) out += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
  return out;
}

const std::vector<testcases::BSDFCase>& bsdfCases() {
  static const std::vector<testcases::BSDFCase> cases = testcases::bsdfCases();
  return cases;
}
// The every-run family: the BxDF cases and the BSDF cases share one Sidak correction.
int normalFamilySize() { return int(normalCases().size() + bsdfCases().size()); }

class BxDFChiSquare : public testing::TestWithParam<int> {};

TEST_P(BxDFChiSquare, SamplesFollowPdf) {
  const auto& cases = normalCases();
  checkCase(cases[GetParam()], normalFamilySize(), 1000 + uint64_t(GetParam()));
}

INSTANTIATE_TEST_SUITE_P(Cases, BxDFChiSquare, testing::Range(0, int(normalCases().size())),
                         [](const testing::TestParamInfo<int>& i) {
                           return caseName(normalCases()[i.param].name);
                         });

// BSDF::sampleF picks a component with u0 and returns the mixture's value and pdf; picks of a
// specular component are delta samples, outside what pdf() describes (the failed-sample cell).
class BSDFChiSquare : public testing::TestWithParam<int> {};

TEST_P(BSDFChiSquare, SamplesFollowPdf) {
  const testcases::BSDFCase& c = bsdfCases()[GetParam()];
  const BSDF& b = *c.bsdf;
  int64_t pdfMismatch = 0, fMismatch = 0;
  stats::DirectionDraw draw = [&](Float u0, const Point2f& u, Vector3f* wi) {
    Float pdf = 0;
    BxDFType type;
    Spectrum f = b.sampleF(c.wo, wi, u0, u, &pdf, kAllBxDF, &type);
    if (pdf == 0 || (type & kSpecular)) return false;
    if (!close(pdf, b.pdf(c.wo, *wi), 1e-3)) ++pdfMismatch;
    Spectrum fe = b.f(c.wo, *wi);
    for (int k = 0; k < 3; ++k)
      if (!close(f[k], fe[k], 1e-3)) ++fMismatch;
    return true;
  };
  // The histogram is over world directions; the pdf takes them as they are.
  auto pdf = [&](const Vector3f& wi) { return double(b.pdf(c.wo, wi)); };
  stats::FitResult r = stats::chiSquareFit(draw, pdf, kSamples, 3000 + uint64_t(GetParam()));
  EXPECT_GT(r.pValue, stats::sidak(kSuiteAlpha, normalFamilySize()))
      << c.name << ": " << r.summary();
  EXPECT_EQ(pdfMismatch, 0) << c.name;
  EXPECT_EQ(fMismatch, 0) << c.name;
  EXPECT_NEAR(r.pdfIntegral, 1 - double(r.failed) / double(r.samples), 0.01) << r.summary();
  if (getenv("CANDELA_VERBOSE_STATS")) std::cout << c.name << ": " << r.summary() << "\n";
}

INSTANTIATE_TEST_SUITE_P(Cases, BSDFChiSquare, testing::Range(0, int(bsdfCases().size())),
                         [](const testing::TestParamInfo<int>& i) {
                           return caseName(bsdfCases()[i.param].name);
                         });

// The full sweep: ~200 cases, about a minute.
class LongBxDFChiSquare : public testing::TestWithParam<int> {};

TEST_P(LongBxDFChiSquare, SamplesFollowPdf) {
  const auto& cases = sweepCases();
  checkCase(cases[GetParam()], int(cases.size()), 5000 + uint64_t(GetParam()));
}

INSTANTIATE_TEST_SUITE_P(Long, LongBxDFChiSquare, testing::Range(0, int(sweepCases().size())),
                         [](const testing::TestParamInfo<int>& i) {
                           return caseName(sweepCases()[i.param].name);
                         });

}  // namespace
}  // namespace candela
