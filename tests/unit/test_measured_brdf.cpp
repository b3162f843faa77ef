// Measured BRDF files (pbrt-v2's "measured" material): a synthetic MERL binary written here and
// read back cell by cell, the text format's parser and its errors, and a real pbrt-v2 .brdf file
// from the shared scenes (skipped with a message when they are absent).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "core/error.h"
#include "parser/spectrum_input.h"
#include "reflection/irregular_brdf.h"
#include "reflection/merl_brdf.h"

namespace candela {
namespace {

namespace fs = std::filesystem;

fs::path tempPath(const std::string& name) {
  return fs::temp_directory_path() /
         ("candela_measured_" + std::to_string(::getpid()) + "_" + name);
}

// (wo, wi) with the given half and difference angles (phi_h = 0): h tilted by theta_h about y,
// wi = the difference vector rotated from h's frame, wo its mirror about h.
void fromHalfDifference(double thetaH, double thetaD, double phiD, Vector3f* wo, Vector3f* wi) {
  double dx = std::sin(thetaD) * std::cos(phiD), dy = std::sin(thetaD) * std::sin(phiD),
         dz = std::cos(thetaD);
  double ct = std::cos(thetaH), st = std::sin(thetaH);
  Vector3f i(Float(dx * ct + dz * st), Float(dy), Float(-dx * st + dz * ct));
  Vector3f h(Float(st), 0, Float(ct));
  *wi = i;
  *wo = 2 * dot(i, h) * h - i;
}

// Cell value written by the synthetic file: distinct per cell and channel.
double cellValue(int c, size_t index) { return 100.0 * (c + 1) + double(index); }

void writeMerl(const fs::path& p, int nh, int nd, int np, bool truncate = false) {
  std::ofstream out(p, std::ios::binary);
  int32_t dims[3] = {nh, nd, np};
  out.write(reinterpret_cast<const char*>(dims), sizeof(dims));
  size_t n = size_t(nh) * nd * np;
  for (int c = 0; c < 3; ++c)
    for (size_t i = 0; i < n; ++i) {
      if (truncate && c == 2 && i == n - 1) break;
      double v = (i == 5) ? -1.0 : cellValue(c, i);  // cell 5 marked as missing
      out.write(reinterpret_cast<const char*>(&v), sizeof(v));
    }
}

TEST(MeasuredBRDF, HalfDifferenceAnglesRoundTrip) {
  for (double th : {0.05, 0.4, 1.2})
    for (double td : {0.1, 0.7, 1.4})
      for (double pd : {0.2, 1.5, 3.0}) {
        Vector3f wo, wi;
        fromHalfDifference(th, td, pd, &wo, &wi);
        if (wo.z <= 0 || wi.z <= 0) continue;
        HalfDifferenceAngles a = halfDifferenceAngles(wo, wi);
        EXPECT_NEAR(a.thetaH, th, 2e-4) << th << " " << td << " " << pd;
        EXPECT_NEAR(a.thetaD, td, 2e-4);
        EXPECT_NEAR(a.phiD, pd, 2e-3);
        // Swapping the directions turns phi_d by pi, which the table folds away.
        HalfDifferenceAngles b = halfDifferenceAngles(wi, wo);
        EXPECT_NEAR(b.thetaD, td, 2e-4);
        EXPECT_NEAR(b.phiD, pd, 2e-3);
      }
}

TEST(MeasuredBRDF, SyntheticMerlFileRoundTrips) {
  const int nh = 6, nd = 5, np = 8;
  fs::path p = tempPath("tiny.merl");
  writeMerl(p, nh, nd, np);
  ASSERT_TRUE(isMerlBrdfFile(p.string()));
  MerlBrdfTable t = readMerlBrdf(p.string());
  EXPECT_EQ(t.nThetaH(), nh);
  EXPECT_EQ(t.nThetaD(), nd);
  EXPECT_EQ(t.nPhiD(), np);
  const double scale[3] = {1.0 / 1500, 1.15 / 1500, 1.66 / 1500};
  int checked = 0;
  for (int ih = 0; ih < nh; ++ih)
    for (int id = 0; id < nd; ++id)
      for (int ip = 0; ip < np; ++ip) {
        // The centre of the cell: theta_h = (u^2) pi/2 with u at the middle of its bin.
        double u = (ih + 0.5) / nh, thetaH = u * u * M_PI / 2;
        double thetaD = (id + 0.5) / nd * M_PI / 2, phiD = (ip + 0.5) / np * M_PI;
        Vector3f wo, wi;
        fromHalfDifference(thetaH, thetaD, phiD, &wo, &wi);
        if (wo.z <= 0.01f || wi.z <= 0.01f) continue;
        size_t index = (size_t(ih) * nd + id) * np + ip;
        Spectrum f = MeasuredBRDF(&t).f(wo, wi);
        for (int c = 0; c < 3; ++c) {
          double expect = index == 5 ? 0.0 : cellValue(c, index) * scale[c];
          EXPECT_NEAR(f[c], expect, 1e-5 * expect) << ih << " " << id << " " << ip;
        }
        // Reciprocal, and two-sided.
        EXPECT_EQ(t.lookup(wi, wo), f);
        EXPECT_EQ(t.lookup(-wo, -wi), f);
        ++checked;
      }
  EXPECT_GT(checked, nh * nd * np / 3);
  EXPECT_TRUE(t.lookup(Vector3f(0, 0, 1), Vector3f(0, 0.6f, -0.8f)).isBlack());
  fs::remove(p);
}

TEST(MeasuredBRDF, MerlErrorsNameTheFile) {
  EXPECT_THROW(readMerlBrdf("/nonexistent/x.merl"), FileError);
  fs::path p = tempPath("truncated.merl");
  writeMerl(p, 4, 4, 4, true);
  EXPECT_FALSE(isMerlBrdfFile(p.string()));
  try {
    readMerlBrdf(p.string());
    ADD_FAILURE() << "no error";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find(p.string()), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("size"), std::string::npos);
  }
  {
    std::ofstream out(p, std::ios::binary | std::ios::trunc);
    int32_t dims[3] = {90, -90, 180};
    out.write(reinterpret_cast<const char*>(dims), sizeof(dims));
  }
  EXPECT_THROW(readMerlBrdf(p.string()), FileError);
  {
    std::ofstream out(p, std::ios::binary | std::ios::trunc);
    out << "ab";
  }
  EXPECT_THROW(readMerlBrdf(p.string()), FileError);
  fs::remove(p);
}

// Found by fuzz_merl: dimensions whose product wraps around 64 bits (2^21 x 2^21 x 2^22 = 2^64)
// made a 12-byte header-only file a valid empty table that lookups read past.
TEST(MeasuredBRDF, MerlDimensionsWhoseProductWrapsAreRefused) {
  const int32_t dims[3] = {1 << 21, 1 << 21, 1 << 22};
  std::string bytes(reinterpret_cast<const char*>(dims), sizeof dims);
  try {
    parseMerlBrdf(bytes, "wrap.merl");
    ADD_FAILURE() << "no error";
  } catch (const FileError& e) {
    EXPECT_NE(
        std::string(e.what()).find("wrap.merl: error: MERL BRDF header has invalid dimensions"),
        std::string::npos)
        << e.what();
  }
  fs::path p = tempPath("wrap.merl");
  {
    std::ofstream out(p, std::ios::binary | std::ios::trunc);
    out << bytes;
  }
  EXPECT_FALSE(isMerlBrdfFile(p.string()));
  fs::remove(p);
}

// Found by fuzz_merl: a finite double beyond float's range (1e231 in the green table) became an
// infinite table value.
TEST(MeasuredBRDF, MerlValuesBeyondTheFloatRangeAreRefused) {
  const int32_t dims[3] = {1, 1, 1};
  const double rgb[3] = {0, 1e231, 72};
  std::string bytes(reinterpret_cast<const char*>(dims), sizeof dims);
  bytes.append(reinterpret_cast<const char*>(rgb), sizeof rgb);
  try {
    parseMerlBrdf(bytes, "big.merl");
    ADD_FAILURE() << "no error";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("big.merl: error: MERL BRDF data holds a value beyond"),
              std::string::npos)
        << e.what();
  }
  const double large[3] = {1e40, -1e300, 72};  // within range once scaled; negative = no data
  bytes.replace(sizeof dims, sizeof large, reinterpret_cast<const char*>(large), sizeof large);
  MerlBrdfTable t = parseMerlBrdf(bytes, "large.merl");
  Spectrum f = t.lookup(Vector3f(0, 0, 1), Vector3f(0, 0, 1));
  EXPECT_FLOAT_EQ(f[0], float(1e40 * MerlBrdfTable::kRedScale));
  EXPECT_EQ(f[1], 0);
}

// Spectral values to RGB the way the scene reader converts reflectances.
Spectrum toRGB(std::span<const Float> lambda, std::span<const Float> values) {
  std::vector<SpectrumSample> s;
  for (size_t i = 0; i < lambda.size(); ++i) s.push_back({lambda[i], values[i]});
  return spectrumSamplesToRGB(s, SpectrumUse::Reflectance);
}

TEST(MeasuredBRDF, IrregularTextFormatParses) {
  fs::path p = tempPath("tiny.brdf");
  {
    std::ofstream out(p);
    out << "# num wls\n2\n# wls\n500 600\n# samples\n"
        << "0.5 0 0.5 3.14159265 0.2 0.2\n"
        << "0.3 0 0.6 1.0 0.4 0.4  # trailing comment\n"
        << "1.0 0.5 0.2 -2.0 0.1 0.1\n";
  }
  IrregularBrdfTable t = readIrregularBrdf(p.string(), toRGB);
  ASSERT_EQ(t.samples().size(), 3u);
  // A flat spectrum converts to grey of the same value.
  EXPECT_NEAR(t.samples()[1].value[0], 0.4f, 2e-3f);
  EXPECT_NEAR(t.samples()[1].value[2], 0.4f, 2e-3f);
  EXPECT_NEAR(t.samples()[0].wo.x, -std::sin(0.5f), 1e-6f);
  EXPECT_NEAR(t.samples()[2].wi.z, std::cos(1.0f), 1e-6f);
  // With three samples every lookup blends those within its radius, so only bounds hold.
  Spectrum f = IrregularMeasuredBRDF(&t).f(t.samples()[0].wo, t.samples()[0].wi);
  EXPECT_GE(f[1], 0.1f - 1e-3f);
  EXPECT_LE(f[1], 0.4f + 1e-3f);
  fs::remove(p);
}

// A record whose values give an infinite colour (1e300 is a finite double) is refused: lookups
// would average it into infinity or NaN.
TEST(MeasuredBRDF, IrregularValuesBeyondTheFloatRangeAreRefused) {
  try {
    parseIrregularBrdf("1\n550\n0 0 0 0 0.5\n0.5 0 0.5 1 1e300\n", "big.brdf", toRGB);
    ADD_FAILURE() << "no error";
  } catch (const FileError& e) {
    EXPECT_NE(
        std::string(e.what()).find(
            "big.brdf: error: line 4: the record's values give a colour beyond the float range"),
        std::string::npos)
        << e.what();
  }
  EXPECT_EQ(parseIrregularBrdf("1\n550\n0 0 0 0 1e30\n", "ok.brdf", toRGB).samples().size(), 1u);
}

TEST(MeasuredBRDF, IrregularErrorsNameTheFileAndLine) {
  fs::path p = tempPath("bad.brdf");
  auto expectError = [&](const std::string& text, const std::string& fragment) {
    {
      std::ofstream out(p, std::ios::trunc);
      out << text;
    }
    try {
      readIrregularBrdf(p.string(), toRGB);
      ADD_FAILURE() << "no error for: " << text;
    } catch (const FileError& e) {
      std::string m = e.what();
      EXPECT_NE(m.find(p.string()), std::string::npos) << m;
      EXPECT_NE(m.find(fragment), std::string::npos) << m;
    }
  };
  expectError("", "no data");
  expectError("2\n500 600\n0.5 0 0.5 0 0.1\n", "incomplete");
  expectError("2\n500 600\n0.5 0 0.5 0 0.1 zebra\n", "line 3");
  expectError("1.5\n500\n", "wavelength count");
  expectError("1\n500\n", "no samples");
  expectError("1\n500\n2.0 0 0.5 0 0.1\n", "polar angles");
  expectError("3\n500 600\n", "incomplete");
  EXPECT_THROW(readIrregularBrdf("/nonexistent/x.brdf", toRGB), FileError);
  fs::remove(p);
}

TEST(MeasuredBRDF, RealPbrtV2FileHasPlausibleValues) {
  fs::path p = fs::path(CANDELA_SHARED_SCENES_DIR) / "pbrt-v2" / "brdfs" / "garnet_red.brdf";
  if (!fs::exists(p)) GTEST_SKIP() << "shared scenes not found: " << p;
  EXPECT_FALSE(isMerlBrdfFile(p.string()));
  IrregularBrdfTable t = readIrregularBrdf(p.string(), toRGB);
  // 31 wavelengths, 1439 records of theta_i in 10..80 degrees.
  ASSERT_EQ(t.samples().size(), 1439u);
  IrregularMeasuredBRDF b(&t);
  for (const IrregularBrdfSample& s : t.samples()) {
    ASSERT_TRUE(s.value.isFinite());
    EXPECT_GE(s.value.maxComponent(), 0);
  }
  // Garnet red: red reflects more than blue on average.
  Spectrum mean(0);
  for (const IrregularBrdfSample& s : t.samples()) mean += s.value;
  EXPECT_GT(mean[0], mean[2]);
  // Albedo at or below 1 at every incidence the data cover (cosine-sampled, 64 x 64 strata;
  // a fixed seed).
  RNG rng(11);
  for (Float theta : {10.f, 30.f, 50.f, 70.f, 80.f}) {
    Vector3f wo(std::sin(radians(theta)), 0, std::cos(radians(theta)));
    Spectrum rho = rhoStratified(b, wo, 64, rng);
    EXPECT_LE(rho.maxComponent(), 1) << theta;
    EXPECT_GT(rho.maxComponent(), 0.01f) << theta;
  }
  // Reciprocity: both orders of a pair reduce to the same point (pbrt 2e §8.6), so exact.
  for (int i = 0; i < 500; ++i) {
    auto d = [&] {
      Float z = 0.2f + 0.8f * rng.uniformFloat(), phi = 2 * kPi * rng.uniformFloat();
      Float s = std::sqrt(1 - z * z);
      return Vector3f(s * std::cos(phi), s * std::sin(phi), z);
    };
    Vector3f wo = d(), wi = d();
    EXPECT_EQ(b.f(wo, wi), b.f(wi, wo));
  }
}

}  // namespace
}  // namespace candela
