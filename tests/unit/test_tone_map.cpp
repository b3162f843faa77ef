// lrt's tone maps (lrt draft §8.4), checked against their definitions.
#include <gtest/gtest.h>

#include <cmath>

#include "film/tonemap/tone_map.h"

namespace candela {
namespace {

ImageBuffer ramp() {
  ImageBuffer img(8, 1, {"R", "G", "B", "A"});
  for (int x = 0; x < 8; ++x)
    for (int c = 0; c < 3; ++c) img.at(x, 0, c) = 0.01f * std::pow(3.f, float(x));
  for (int x = 0; x < 8; ++x) img.at(x, 0, 3) = 1;
  return img;
}

float y(const ImageBuffer& img, int x) {
  return 0.212671f * img.at(x, 0, 0) + 0.715160f * img.at(x, 0, 1) + 0.072169f * img.at(x, 0, 2);
}

TEST(ToneMap, MaxWhiteMapsTheBrightestPixelToOne) {
  ImageBuffer img = ramp();
  applyToneMap(img, "maxwhite", ParamSet(), FileLoc{});
  EXPECT_NEAR(y(img, 7), 1, 1e-5);
  EXPECT_NEAR(y(img, 6), 1.f / 3, 1e-5);  // linear: ratios kept
  EXPECT_EQ(img.at(3, 0, 3), 1);          // alpha untouched
}

TEST(ToneMap, ContrastFollowsWardsFactor) {
  ImageBuffer img = ramp();
  double logSum = 0;
  for (int x = 0; x < 8; ++x) logSum += std::log(683.0 * y(img, x));
  double Ywa = std::exp(logSum / 8);
  double s = std::pow((1.219 + std::pow(50.0, 0.4)) / (1.219 + std::pow(Ywa, 0.4)), 2.5);
  float before = y(img, 2);
  applyToneMap(img, "contrast", ParamSet(), FileLoc{});
  EXPECT_NEAR(y(img, 2), before * 683 * s / 100, 1e-4 * y(img, 2));
}

TEST(ToneMap, NonlinearCompressesIntoTheDisplayRange) {
  ImageBuffer img = ramp();
  applyToneMap(img, "nonlinear", ParamSet(), FileLoc{});
  EXPECT_NEAR(y(img, 7), 1, 1e-4);  // the white point
  for (int x = 1; x < 8; ++x) EXPECT_GT(y(img, x), y(img, x - 1));
}

TEST(ToneMap, HighContrastCapacityIsContinuousWithNaturalLogs) {
  for (double at : {0.0034, 1.0, 7.2444}) {
    double below = highContrastCapacity(at * (1 - 1e-9)), above = highContrastCapacity(at);
    // At 0.0034 the draft's constants meet to 1%; at 1 and 7.2444 to the printed digits.
    EXPECT_NEAR(below, above, at < 0.01 ? 0.03 : 2e-3) << at;
  }
  // A slow horizontal gradient over three decades: locally almost uniform, so the local
  // adaptation luminance is close to each pixel's own and the capacity curve shows through:
  // monotone, darkest near 0, brightest at the top of the display.
  ImageBuffer img(256, 4, {"R", "G", "B"});
  for (int yy = 0; yy < 4; ++yy)
    for (int x = 0; x < 256; ++x)
      for (int c = 0; c < 3; ++c) img.at(x, yy, c) = 1e-4f * std::pow(10.f, 3.f * x / 255.f);
  applyToneMap(img, "highcontrast", ParamSet(), FileLoc{});
  auto lum = [&](int x) {
    return 0.212671f * img.at(x, 1, 0) + 0.715160f * img.at(x, 1, 1) + 0.072169f * img.at(x, 1, 2);
  };
  for (int x = 1; x < 256; ++x) EXPECT_GE(lum(x), lum(x - 1) * (1 - 1e-4f)) << x;
  EXPECT_LT(lum(0), 0.05);

  // Two uniform halves: far from their border every window the operator tries is uniform, so
  // the adaptation luminance is the pixel's own and the capacity curve maps the dimmest to 0 and
  // the brightest to display white exactly.
  ImageBuffer halves(512, 4, {"R", "G", "B"});
  for (int yy = 0; yy < 4; ++yy)
    for (int x = 0; x < 512; ++x)
      for (int c = 0; c < 3; ++c) halves.at(x, yy, c) = x < 256 ? 0.001f : 0.5f;
  applyToneMap(halves, "highcontrast", ParamSet(), FileLoc{});
  auto lumH = [&](int x) {
    return 0.212671f * halves.at(x, 1, 0) + 0.715160f * halves.at(x, 1, 1) +
           0.072169f * halves.at(x, 1, 2);
  };
  EXPECT_NEAR(lumH(20), 0, 1e-6);
  EXPECT_NEAR(lumH(490), 1, 1e-4);
}

TEST(ToneMap, UnknownNameIsAnErrorListingTheOperators) {
  ImageBuffer img = ramp();
  try {
    applyToneMap(img, "filmic", ParamSet(), FileLoc{"s.pbrt", 4, 1});
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("s.pbrt:4:1"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("highcontrast"), std::string::npos);
  }
}

}  // namespace
}  // namespace candela
