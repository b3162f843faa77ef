// Sampling of tabulated Fourier BSDFs (pbrt 3e §8.6.2) against their pdf: 1M samples per case
// into the 20 x 40 (theta, phi) histogram of direction_stats.h, significance 0.01 for the family
// (Sidak-corrected per case), fixed seeds. The tables come from the test writer: the Fejer lobes
// (sampled in proportion to f |cos|), a diffuse transmitter with eta = 1.5, and a table whose
// a_0 is cubic in mu_i and depends on mu_o, which Catmull-Rom interpolates inexactly, so the
// inversion in mu and phi is exercised off its exact cases. Along the way: sampleF's pdf and
// value are pdf() and f(), and the pdf integrates to 1 within 1%.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>

#include "direction_stats.h"
#include "reflection/fourier_bxdf.h"
#include "support/fourier_bsdf_writer.h"

namespace candela {
namespace {

namespace fs = std::filesystem;

constexpr double kFamilyAlpha = 0.01;
constexpr int64_t kSamples = 1000000;

std::shared_ptr<const FourierBsdfTable> table(const test::FourierBsdfModel& model,
                                              const std::string& name) {
  fs::path p = fs::temp_directory_path() /
               ("candela_fourier_stats_" + std::to_string(::getpid()) + "_" + name + ".bsdf");
  test::writeBytes(p.string(), test::fourierBsdfFileBytes(model, test::splitUniformNodes(10)));
  auto t = std::make_shared<const FourierBsdfTable>(readFourierBsdf(p.string()));
  fs::remove(p);
  return t;
}

// Reflection a_k = |mu_i| (0.3 + mu_i^2 + 0.5 |mu_o|) (1, 0.6 g, 0.2 g)_k with g = (1 - mu_i^2)
// (1 - mu_o^2), so that the azimuthal terms vanish at the poles where phi is undefined;
// transmission a_0 = 0.4 |mu_i|^3 (1 + mu_o^2); eta 1.33.
test::FourierBsdfModel uneven() {
  test::FourierBsdfModel m;
  m.orders = 3;
  m.eta = 1.33f;
  m.coefficients = [](double muI, double muO) {
    double ai = std::abs(muI), ao = std::abs(muO);
    if (test::isReflection(muI, muO)) {
      double s = ai * (0.3 + muI * muI + 0.5 * ao), g = (1 - muI * muI) * (1 - muO * muO);
      return std::vector<double>{s, 0.6 * g * s, 0.2 * g * s};
    }
    return std::vector<double>{0.4 * ai * ai * ai * (1 + muO * muO), 0, 0};
  };
  return m;
}

struct Case {
  std::string name;
  std::shared_ptr<const FourierBsdfTable> table;
  Vector3f wo;
};

Vector3f direction(double thetaDeg, double phiDeg) {
  double t = thetaDeg * M_PI / 180, p = phiDeg * M_PI / 180;
  return Vector3f(Float(std::sin(t) * std::cos(p)), Float(std::sin(t) * std::sin(p)),
                  Float(std::cos(t)));
}

const std::vector<Case>& cases() {
  static const std::vector<Case> c = [] {
    auto fejer = table(test::fejerModel(0.8, 0.5, 0.2, 8), "fejer");
    auto transmitter = table(test::diffuseTransmitterModel(0.3, 0.5, 1.5f), "transmitter");
    auto wavy = table(uneven(), "uneven");
    return std::vector<Case>{
        {"fejer_theta20", fejer, direction(20, 30)},
        {"fejer_theta75_below", fejer, direction(180 - 75, 200)},
        {"transmitter_theta40", transmitter, direction(40, 10)},
        {"transmitter_theta60_below", transmitter, direction(180 - 60, 100)},
        {"uneven_theta0", wavy, direction(0, 0)},
        {"uneven_theta55", wavy, direction(55, 300)},
        {"uneven_theta80_below", wavy, direction(180 - 80, 45)},
    };
  }();
  return c;
}

bool close(double a, double b, double rel) {
  return std::abs(a - b) <= rel * std::max(std::abs(a), std::abs(b)) + 1e-30;
}

class FourierChiSquare : public testing::TestWithParam<int> {};

TEST_P(FourierChiSquare, SamplesFollowPdf) {
  const Case& c = cases()[size_t(GetParam())];
  FourierBSDF b(c.table.get());
  int64_t pdfMismatch = 0, fMismatch = 0;
  stats::DirectionDraw draw = [&](Float, const Point2f& u, Vector3f* wi) {
    Float pdf = 0;
    Spectrum f = b.sampleF(c.wo, wi, u, &pdf);
    if (pdf == 0) return false;
    // Float rounding of the two code paths: a relative 1e-3 is far above it.
    if (!close(pdf, b.pdf(c.wo, *wi), 1e-3)) ++pdfMismatch;
    Spectrum fe = b.f(c.wo, *wi);
    for (int k = 0; k < 3; ++k)
      if (!close(f[k], fe[k], 1e-3)) ++fMismatch;
    return true;
  };
  auto pdf = [&](const Vector3f& wi) { return double(b.pdf(c.wo, wi)); };
  stats::FitResult r = stats::chiSquareFit(draw, pdf, kSamples, 7000 + uint64_t(GetParam()));
  EXPECT_GT(r.pValue, stats::sidak(kFamilyAlpha, int(cases().size())))
      << c.name << ": " << r.summary();
  EXPECT_EQ(pdfMismatch, 0) << c.name;
  EXPECT_EQ(fMismatch, 0) << c.name;
  EXPECT_EQ(r.failed, 0) << c.name;
  EXPECT_NEAR(r.pdfIntegral, 1, 0.01) << c.name << ": " << r.summary();
  if (getenv("CANDELA_VERBOSE_STATS")) std::cout << c.name << ": " << r.summary() << "\n";
}

INSTANTIATE_TEST_SUITE_P(Cases, FourierChiSquare, testing::Range(0, int(cases().size())),
                         [](const testing::TestParamInfo<int>& i) {
                           return cases()[size_t(i.param)].name;
                         });

// White furnace on the BxDF: the integral of f |cos theta_i| over the sphere (adaptive cubature,
// the horizon on a cell border) is the albedo at every outgoing angle, per channel.
TEST(FourierFurnace, LambertianAndFejerTablesReflectTheirAlbedo) {
  auto lambert = table(test::lambertianModel(0.6), "furnace_lambert");
  auto fejer = table(test::fejerModel(0.8, 0.5, 0.2, 8), "furnace_fejer");
  FourierBSDF bl(lambert.get()), bf(fejer.get());
  const double rho[3] = {0.8, 0.5, 0.2};
  // Outgoing angles outside the first mu interval next to the horizon (|mu_o| >= 0.1), where
  // the tables are exact.
  for (double theta : {0.0, 30.0, 60.0, 84.0}) {
    Vector3f wo = direction(theta, 15);
    double r = stats::integrateSphere(
        [&](const Vector3f& wi) { return double(bl.f(wo, wi)[1]) * std::abs(wi.z); });
    EXPECT_NEAR(r, 0.6, 1e-4) << theta;
    // The Fejer lobes depend on phi even at the pole, where it is undefined (taken as 0).
    if (theta == 0) continue;
    for (int ch = 0; ch < 3; ++ch) {
      double rf = stats::integrateSphere(
          [&](const Vector3f& wi) { return double(bf.f(wo, wi)[ch]) * std::abs(wi.z); });
      EXPECT_NEAR(rf, rho[ch], 1e-4) << theta << " channel " << ch;
    }
  }
}

}  // namespace
}  // namespace candela
