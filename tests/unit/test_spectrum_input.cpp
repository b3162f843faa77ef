#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/cie_data.h"
#include "core/error.h"
#include "parser/spectrum_input.h"

using namespace candela;

namespace {

std::vector<SpectrumSample> constant(Float v) { return {{300, v}, {900, v}}; }

std::string pbrtV2Dir() { return std::string(CANDELA_SHARED_SCENES_DIR) + "/pbrt-v2"; }

}  // namespace

TEST(SpectrumCie, TableShapeAndKnownValues) {
  EXPECT_EQ(kCieSamples, 471);
  EXPECT_FLOAT_EQ(kCieY[555 - kCieLambdaStart], 1.0f);  // y peaks at 555 nm by definition
  EXPECT_FLOAT_EQ(kCieX[0], 0.0001299f);
  double sumY = 0;
  for (int i = 0; i < kCieSamples; ++i) sumY += kCieY[i];
  EXPECT_NEAR(sumY, 106.857, 0.01);  // the integral of y over 360-830 nm at 1 nm
}

TEST(SpectrumInput, ConstantReflectanceIsWhite) {
  Spectrum s = spectrumSamplesToRGB(constant(1), SpectrumUse::Reflectance);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(s[c], 1.0, 0.02) << c;
  Float xyz[3];
  spectrumSamplesToXYZ(constant(1), xyz);
  EXPECT_NEAR(xyz[1], 1.0, 1e-5);  // normalised: constant 1 has Y = 1
  Spectrum half = spectrumSamplesToRGB(constant(0.5f), SpectrumUse::Reflectance);
  EXPECT_NEAR(half.g(), 0.5, 0.01);
}

TEST(SpectrumInput, UnsortedSamplesAndClampingOutsideTheRange) {
  // A single-sample or out-of-order SPD is still a well-defined piecewise-linear function.
  Spectrum a = spectrumSamplesToRGB({{500, 1}}, SpectrumUse::Reflectance);
  Spectrum b = spectrumSamplesToRGB({{700, 1}, {400, 1}, {550, 1}}, SpectrumUse::Reflectance);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(a[c], 1.0, 0.02);
    EXPECT_NEAR(b[c], 1.0, 0.02);
  }
  EXPECT_TRUE(spectrumSamplesToRGB({}, SpectrumUse::Reflectance).isBlack());
}

TEST(SpectrumInput, NarrowBandsHaveTheExpectedHue) {
  // 450 nm reads blue, 610 nm red (lrt draft §5.1.2's matching curves).
  Spectrum blue = spectrumSamplesToRGB({{445, 0}, {450, 1}, {455, 0}}, SpectrumUse::Illuminant);
  Spectrum red = spectrumSamplesToRGB({{605, 0}, {610, 1}, {615, 0}}, SpectrumUse::Illuminant);
  EXPECT_GT(blue.b(), blue.r());
  EXPECT_GT(blue.b(), blue.g());
  EXPECT_GT(red.r(), red.g());
  EXPECT_GT(red.r(), red.b());
}

TEST(SpectrumInput, EmissionParametersAreIlluminants) {
  EXPECT_EQ(spectrumUseForParameter("L"), SpectrumUse::Illuminant);
  EXPECT_EQ(spectrumUseForParameter("I"), SpectrumUse::Illuminant);
  EXPECT_EQ(spectrumUseForParameter("Kd"), SpectrumUse::Reflectance);
  EXPECT_EQ(spectrumUseForParameter("eta"), SpectrumUse::Reflectance);
}

TEST(SpectrumInput, PlanckAndBlackbody) {
  // Wien: a 5778 K black body peaks near 501.5 nm.
  double peak = planck(501.5, 5778);
  EXPECT_GT(peak, planck(450, 5778));
  EXPECT_GT(peak, planck(560, 5778));
  EXPECT_EQ(planck(500, 1), 0.0);  // underflows cleanly, no NaN
  Spectrum warm = blackbodyToRGB(2700, 1), cool = blackbodyToRGB(10000, 1);
  EXPECT_GT(warm.r(), warm.b());
  EXPECT_GT(cool.b(), cool.r());
  Spectrum d = blackbodyToRGB(6500, 1), d2 = blackbodyToRGB(6500, 2);
  EXPECT_NEAR(d2.g(), 2 * d.g(), 1e-4);
  // A 6500 K black body is close to D65 white: near-equal RGB.
  EXPECT_NEAR(d.r() / d.g(), 1.0, 0.1);
  EXPECT_NEAR(d.b() / d.g(), 1.0, 0.15);
  EXPECT_TRUE(blackbodyToRGB(1, 1).isFinite());
  EXPECT_TRUE(blackbodyToRGB(1e30f, 1).isFinite());
}

TEST(SpectrumInput, ReadsSpdFiles) {
  std::filesystem::path p = std::filesystem::temp_directory_path() / "candela_test_flat.spd";
  {
    std::ofstream f(p);
    f << "# a flat spectrum\n300 1 # first\n  900\t1\n\n";
  }
  std::vector<SpectrumSample> s = readSpectrumFile(p.string());
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[1].lambda, 900);
  {
    std::ofstream f(p);
    f << "300 1\n400 abc\n";
  }
  try {
    readSpectrumFile(p.string());
    FAIL() << "expected an error";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("line 2: expected a number, found 'abc'"),
              std::string::npos)
        << e.what();
  }
  {
    std::ofstream f(p);
    f << "300 1 400\n";
  }
  EXPECT_THROW(readSpectrumFile(p.string()), FileError);
  std::filesystem::remove(p);
  EXPECT_THROW(readSpectrumFile(p.string()), FileError);
}

TEST(SpectrumInputExternal, D65FileIsNearWhite) {
  std::string path = pbrtV2Dir() + "/spds/cie.stdillum.D6500.spd";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared scenes not found: " << path;
  Spectrum d65 = spectrumSamplesToRGB(readSpectrumFile(path), SpectrumUse::Illuminant);
  // The RGB space's white is D65: equal components (chromaticity 1/3, 1/3 in rgb).
  Float sum = d65.r() + d65.g() + d65.b();
  EXPECT_NEAR(d65.r() / sum, 1.0 / 3, 0.01);
  EXPECT_NEAR(d65.g() / sum, 1.0 / 3, 0.01);
  Float xyz[3];
  spectrumSamplesToXYZ(readSpectrumFile(path), xyz);
  Float xs = xyz[0] + xyz[1] + xyz[2];
  EXPECT_NEAR(xyz[0] / xs, 0.3127, 0.002);  // CIE D65 chromaticity x, y
  EXPECT_NEAR(xyz[1] / xs, 0.3290, 0.002);
}

TEST(SpectrumInputExternal, GoldIsYellowish) {
  // Gold's extinction coefficient k rises toward the red.
  std::string path = pbrtV2Dir() + "/spds/metals/Au.k.spd";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared scenes not found: " << path;
  Spectrum k = spectrumSamplesToRGB(readSpectrumFile(path), SpectrumUse::Reflectance);
  EXPECT_GT(k.r(), k.g());
  EXPECT_GT(k.g(), k.b());
}
