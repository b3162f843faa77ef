// pbrt-v3's tabulated Fourier BSDFs (pbrt 3e §8.6): the Catmull-Rom and Fourier helpers, files
// written by the test writer (tests/support/fourier_bsdf_writer.h) from BSDFs whose series are
// known, read back and evaluated, and malformed files refused with the path and the reason.
// The test BSDFs are linear in |mu_i| and independent of mu_o on each side of the surface, which
// Catmull-Rom splines reproduce exactly (the ends use one-sided differences, exact for lines);
// the only interpolation error is in the first interval of mu_o next to mu_o = 0, where the
// BSDFs jump, so the evaluation checks keep |mu_o| >= 1 / nHalf and hold to float rounding.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>

#include "core/error.h"
#include "core/rng.h"
#include "reflection/catmull_rom.h"
#include "reflection/fourier_bsdf_table.h"
#include "reflection/fourier_bxdf.h"
#include "reflection/fourier_series.h"
#include "support/fourier_bsdf_writer.h"

namespace candela {
namespace {

namespace fs = std::filesystem;

constexpr int kHalf = 8;  // nodes per side: mu = k / 8

fs::path tempPath(const std::string& name) {
  return fs::temp_directory_path() /
         ("candela_fourier_" + std::to_string(::getpid()) + "_" + name + ".bsdf");
}

// A table written to disk and read back (the reader's path, not a shortcut).
FourierBsdfTable tableFrom(const test::FourierBsdfModel& model, const std::string& name) {
  fs::path p = tempPath(name);
  test::writeBytes(p.string(), test::fourierBsdfFileBytes(model, test::splitUniformNodes(kHalf)));
  FourierBsdfTable t = readFourierBsdf(p.string());
  fs::remove(p);
  return t;
}

Vector3f direction(double theta, double phi) {
  return Vector3f(Float(std::sin(theta) * std::cos(phi)), Float(std::sin(theta) * std::sin(phi)),
                  Float(std::cos(theta)));
}

// Polar angles whose cosines stay outside the first interval next to mu = 0 (|mu| >= 1/8).
const double kThetas[] = {0.0, 0.3, 0.7, 1.1, 1.44};

TEST(CatmullRom, WeightsSumToOneAndReproduceLines) {
  std::vector<Float> nodes = {-1, -0.7f, -0.2f, 0, 0, 0.1f, 0.5f, 0.55f, 1};
  for (Float x = -1; x <= 1; x += 0.01f) {
    int off;
    Float w[4];
    ASSERT_TRUE(catmullRomWeights(nodes, x, &off, w)) << x;
    double sum = 0, line = 0;
    for (int k = 0; k < 4; ++k) {
      if (w[k] == 0) continue;
      ASSERT_GE(off + k, 0);
      ASSERT_LT(off + k, int(nodes.size()));
      sum += w[k];
      line += w[k] * (3 * nodes[size_t(off + k)] - 0.5);
    }
    EXPECT_NEAR(sum, 1, 1e-6) << x;
    EXPECT_NEAR(line, 3 * x - 0.5, 1e-5) << x;
  }
  int off;
  Float w[4];
  EXPECT_FALSE(catmullRomWeights(nodes, -1.001f, &off, w));
  EXPECT_FALSE(catmullRomWeights(nodes, 1.001f, &off, w));
}

TEST(CatmullRom, InteriorOfUniformNodesReproducesQuadratics) {
  // Central differences are exact derivatives of a quadratic on uniform nodes.
  std::vector<Float> nodes, values;
  for (int i = 0; i <= 10; ++i) {
    nodes.push_back(Float(i) / 10);
    values.push_back(nodes.back() * nodes.back());
  }
  for (Float x = 0.1f; x <= 0.9f; x += 0.013f) {
    int off;
    Float w[4];
    ASSERT_TRUE(catmullRomWeights(nodes, x, &off, w));
    double v = 0;
    for (int k = 0; k < 4; ++k)
      if (w[k] != 0) v += w[k] * values[size_t(off + k)];
    EXPECT_NEAR(v, x * x, 1e-6) << x;
  }
  // The integral of a line is exact over the whole range (ends included).
  std::vector<Float> line, cdf(nodes.size());
  for (Float x : nodes) line.push_back(2 * x + 1);
  EXPECT_NEAR(integrateCatmullRom(nodes, line, cdf), 2.0, 1e-6);
  EXPECT_NEAR(cdf[5], 0.25 + 0.5, 1e-6);
}

TEST(FourierSeries, RecurrenceMatchesCosines) {
  RNG rng(7);
  std::vector<Float> a(40);
  for (Float& x : a) x = rng.uniformFloat() - 0.5f;
  for (double phi : {0.0, 0.3, 1.7, 3.1, M_PI}) {
    double direct = 0;
    for (size_t k = 0; k < a.size(); ++k) direct += a[k] * std::cos(double(k) * phi);
    EXPECT_NEAR(evaluateFourier(a.data(), int(a.size()), std::cos(phi)), direct, 1e-5) << phi;
  }
}

TEST(FourierSeries, SamplingInvertsTheIntegral) {
  // a = (1, 0.8, 0.3): positive everywhere. The fraction of [0, phi] of the integral on [0, pi]
  // must be the (folded) sample, and the density the series over 2 pi a_0.
  Float a[3] = {1, 0.8f, 0.3f};
  for (Float u : {0.05f, 0.2f, 0.45f, 0.55f, 0.9f}) {
    Float phi, value, pdf;
    ASSERT_TRUE(sampleFourier(a, 3, u, &phi, &value, &pdf));
    double p = std::abs(phi);
    double F = (p + 0.8 * std::sin(p) + 0.3 * std::sin(2 * p) / 2) / M_PI;
    double folded = u < 0.5f ? 2 * u : 2 * u - 1;
    EXPECT_NEAR(F, folded, 1e-5) << u;
    EXPECT_EQ(phi < 0, u >= 0.5f);
    EXPECT_NEAR(value, 1 + 0.8 * std::cos(p) + 0.3 * std::cos(2 * p), 1e-5);
    EXPECT_NEAR(pdf, value / (2 * M_PI), 1e-6);
  }
  Float zero[2] = {0, 1};
  Float phi, value, pdf;
  EXPECT_FALSE(sampleFourier(zero, 2, 0.3f, &phi, &value, &pdf));
}

TEST(FourierBsdfTable, ReadsWhatTheWriterWrote) {
  FourierBsdfTable t = tableFrom(test::fejerModel(0.8, 0.5, 0.2, 6), "roundtrip");
  EXPECT_EQ(t.nMu(), 2 * kHalf + 2);
  EXPECT_EQ(t.mMax(), 6);
  EXPECT_EQ(t.nChannels(), 3);
  EXPECT_EQ(t.eta(), 1);
  // Cell (mu_i = -1, mu_o = 1/2): reflection, channel R's a_1 = 0.5 / pi * 1 * 2 (1 - 1/6).
  int m;
  const Float* a = t.coefficients(0, kHalf + 1 + kHalf / 2, &m);
  ASSERT_EQ(m, 6);
  EXPECT_NEAR(a[m + 1], 0.8 / M_PI * 2 * (1 - 1.0 / 6), 1e-6);
  // Transmission cells store nothing.
  t.coefficients(0, 0, &m);
  EXPECT_EQ(m, 0);
}

TEST(FourierBSDF, LambertianFileIsRhoOverPi) {
  const double rho = 0.6;
  FourierBsdfTable t = tableFrom(test::lambertianModel(rho), "lambert");
  FourierBSDF b(&t);
  for (double to : kThetas)
    for (double ti : kThetas)
      for (double phi : {0.0, 1.0, 2.5}) {
        Vector3f wo = direction(to, 0.4), wi = direction(ti, 0.4 + phi);
        EXPECT_NEAR(b.f(wo, wi)[1], rho / M_PI, 1e-6) << to << " " << ti << " " << phi;
        // Both directions below: reflection seen from the other side.
        EXPECT_NEAR(b.f(-wo, -wi)[0], rho / M_PI, 1e-6);
        // Opposite sides: the table has no transmission.
        EXPECT_EQ(b.f(wo, -wi)[2], 0.f);
      }
}

TEST(FourierBSDF, GlossyRgbFileMatchesItsSeriesPerChannel) {
  const double rho[3] = {0.8, 0.5, 0.2};
  const int n = 6;
  FourierBsdfTable t = tableFrom(test::fejerModel(rho[0], rho[1], rho[2], n), "fejer");
  FourierBSDF b(&t);
  for (double to : kThetas)
    for (double ti : kThetas)
      for (double phi : {0.0, 0.2, 0.9, 2.0, 3.0}) {
        // phi is the azimuth between -wi and wo: wi at azimuth phi_o + pi + phi.
        Vector3f wo = direction(to, 1.0), wi = direction(ti, 1.0 + M_PI + phi);
        // At a pole phi is undefined and taken as 0 (cos phi = 1).
        double p = to == 0 || ti == 0 ? 0 : phi, kernel = 1;
        for (int k = 1; k < n; ++k) kernel += 2 * (1 - double(k) / n) * std::cos(k * p);
        Spectrum f = b.f(wo, wi);
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(f[c], rho[c] / M_PI * kernel, 2e-6 * (1 + kernel))
              << "channel " << c << " theta_o " << to << " theta_i " << ti << " phi " << phi;
      }
}

TEST(FourierBSDF, TransmissionScalesByTheSquaredIndexRatio) {
  const double rho = 0.3, tau = 0.5;
  const float eta = 1.5f;
  FourierBsdfTable t = tableFrom(test::diffuseTransmitterModel(rho, tau, eta), "transmit");
  FourierBSDF b(&t);
  Vector3f above = direction(0.5, 0.3), below = direction(M_PI - 0.9, 2.0);
  Vector3f above2 = direction(1.0, 2.5);
  // Light from below (index eta) leaving above (index 1): radiance scales by (1 / eta)^2.
  EXPECT_NEAR(b.f(above, below)[0], tau / M_PI / (eta * eta), 1e-6);
  // Light from above leaving below: by eta^2.
  EXPECT_NEAR(b.f(below, above)[0], tau / M_PI * eta * eta, 1e-6);
  EXPECT_NEAR(b.f(above, above2)[0], rho / M_PI, 1e-6);
  EXPECT_NEAR(b.f(below, -above2)[0], rho / M_PI, 1e-6);
}

TEST(FourierBSDF, SamplingIsProportionalToFCos) {
  // Both test BSDFs have f |cos theta_i| proportional to the sampling density (in every
  // channel for the Fejer lobes): f |cos| / pdf is the albedo for every sample, up to rounding.
  const double rho[3] = {0.8, 0.5, 0.2};
  FourierBsdfTable lambert = tableFrom(test::lambertianModel(0.6), "lambert_s");
  FourierBsdfTable fejer = tableFrom(test::fejerModel(rho[0], rho[1], rho[2], 6), "fejer_s");
  FourierBSDF bl(&lambert), bf(&fejer);
  RNG rng(11);
  for (double to : kThetas)
    for (int s = 0; s < 2000; ++s) {
      Vector3f wo = direction(to, 0.7);
      if (s % 2) wo = -wo;
      Point2f u(rng.uniformFloat(), rng.uniformFloat());
      Vector3f wi;
      Float pdf;
      BxDFType type;
      Spectrum f = bl.sampleF(wo, &wi, u, &pdf, &type);
      ASSERT_GT(pdf, 0);
      EXPECT_TRUE(sameHemisphere(wo, wi));
      EXPECT_EQ(type, BxDFType(kReflection | kGlossy));
      EXPECT_NEAR(f[0] * absCosTheta(wi) / pdf, 0.6, 2e-4);
      EXPECT_NEAR(pdf, bl.pdf(wo, wi), 1e-4 * pdf);
      // The Fejer table is not a function of direction at the pole, where phi is undefined.
      if (to == 0) continue;
      f = bf.sampleF(wo, &wi, u, &pdf);
      ASSERT_GT(pdf, 0);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(f[c] * absCosTheta(wi) / pdf, rho[c], 2e-4);
      EXPECT_NEAR(pdf, bf.pdf(wo, wi), 1e-4 * pdf);
    }
}

// ---- malformed files -------------------------------------------------------------------------

std::string lambertBytes() {
  return test::fourierBsdfFileBytes(test::lambertianModel(0.5), test::splitUniformNodes(4));
}

void setU32(std::string& bytes, size_t at, uint32_t v) { std::memcpy(bytes.data() + at, &v, 4); }

// The message of the FileError that reading these bytes throws ("" if none).
std::string readError(const std::string& bytes, const std::string& name) {
  fs::path p = tempPath(name);
  test::writeBytes(p.string(), bytes);
  std::string message;
  try {
    readFourierBsdf(p.string());
  } catch (const FileError& e) {
    message = e.what();
  }
  fs::remove(p);
  if (!message.empty()) {
    EXPECT_NE(message.find(p.string()), std::string::npos) << "no path in: " << message;
  }
  return message;
}

TEST(FourierBsdfFile, MissingFileNamesThePath) {
  fs::path p = tempPath("does_not_exist");
  try {
    readFourierBsdf(p.string());
    FAIL() << "no error";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find(p.string()), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("no such file"), std::string::npos) << e.what();
  }
}

TEST(FourierBsdfFile, TruncatedAnywhereIsRefused) {
  std::string good = lambertBytes();
  size_t nMu = 10;
  // In the header, right after it, within mu, within the cdf, the offsets, the coefficients,
  // the metadata, and one byte short.
  std::vector<size_t> cuts = {0,
                              7,
                              40,
                              64,
                              64 + 4 * 5,
                              64 + 4 * nMu + 8,
                              64 + 4 * (nMu + nMu * nMu) + 12,
                              good.size() - 20,
                              good.size() - 1};
  for (size_t cut : cuts) {
    std::string m = readError(good.substr(0, cut), "cut" + std::to_string(cut));
    bool reason = m.find("truncated") != std::string::npos ||
                  m.find("too short for a Fourier BSDF header") != std::string::npos;
    EXPECT_TRUE(reason) << "cut at " << cut << ": " << m;
  }
  EXPECT_EQ(readError(good, "good"), "");
}

TEST(FourierBsdfFile, BadHeadersAreRefusedWithTheReason) {
  struct Case {
    std::string name, expect;
    std::function<void(std::string&)> corrupt;
  };
  std::vector<Case> cases = {
      {"magic", "SCATFUN", [](std::string& b) { b[0] = 'X'; }},
      {"version", "version 2", [](std::string& b) { b[7] = 2; }},
      {"nmu_huge", "nMu = 2147483648", [](std::string& b) { setU32(b, 12, 1u << 31); }},
      {"nmu_one", "nMu = 1", [](std::string& b) { setU32(b, 12, 1); }},
      {"mmax_huge", "mMax = 4294967295", [](std::string& b) { setU32(b, 20, 0xffffffffu); }},
      {"ncoeffs", "add up to", [](std::string& b) { setU32(b, 16, 1u << 30); }},
      {"channels", "2 channels", [](std::string& b) { setU32(b, 24, 2); }},
      {"bases", "4 basis functions", [](std::string& b) { setU32(b, 28, 4); }},
      {"extrapolated", "harmonic extrapolation", [](std::string& b) { setU32(b, 8, 3); }},
      {"not_bsdf", "holds no BSDF", [](std::string& b) { setU32(b, 8, 0); }},
      {"trailing", "add up to", [](std::string& b) { b += "x"; }},
      {"mu_order", "ascending",
       [](std::string& b) {
         std::swap(b[64], b[68]);
         std::swap(b[65], b[69]);
         std::swap(b[66], b[70]);
         std::swap(b[67], b[71]);
       }},
      {"mu_range", "[-1, 1]",
       [](std::string& b) {
         float v = 2;
         std::memcpy(b.data() + 64, &v, 4);
       }},
  };
  for (const Case& c : cases) {
    std::string b = lambertBytes();
    c.corrupt(b);
    std::string m = readError(b, c.name);
    EXPECT_NE(m.find(c.expect), std::string::npos) << c.name << ": " << m;
  }
}

TEST(FourierBsdfFile, CellsOutsideTheCoefficientsAreRefused) {
  std::string b = lambertBytes();
  size_t nMu = 10, offsets = 64 + 4 * (nMu + nMu * nMu);
  // The cell at index 9 (mu_o node 0, mu_i node 9: reflection at mu_o = -1, mu_i = 1) pointed
  // past the end.
  setU32(b, offsets + 8 * 9, 1u << 20);
  std::string m = readError(b, "offset");
  EXPECT_NE(m.find("the cell of mu_i node 9 and mu_o node 0 reaches past the end"),
            std::string::npos)
      << m;
  b = lambertBytes();
  setU32(b, offsets + 8 * 9 + 4, 7);  // longer than mMax = 1
  m = readError(b, "length");
  EXPECT_NE(m.find("more than mMax"), std::string::npos) << m;
  b = lambertBytes();
  float nan = std::nanf("");
  std::memcpy(b.data() + offsets + 8 * nMu * nMu, &nan, 4);
  m = readError(b, "nan");
  EXPECT_NE(m.find("NaN"), std::string::npos) << m;
}

}  // namespace
}  // namespace candela
