// Scenes far from unit size (issue 15). The Cornell box with camera and world scaled together by
// 1e-7, 1e-6 and 1e6 has the image of the box at full size: rays start at the camera (no absolute
// hither plane), and spawning offsets scale with the geometry. Same seed and samples, so the
// images differ only by rounding: the means agree to 1e-4. And geometry at the edge of float's
// range (a sphere of radius 3e38 in an instance, a triangle with vertices at +-3.4e38), which
// crashed two of the accelerators, renders with every pixel finite under all four.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "support/render_scene.h"
#include "support/robustness_figures.h"

namespace candela {
namespace {

double meanOf(const Film& film) { return film.image().rgbMean(); }

// The box with its LookAt's eye and target multiplied by s and the world scaled by s.
std::string scaledBox(const std::string& s) {
  std::string text = test::cornellBoxText(16);
  const std::string lookAt = "LookAt 278 273 -800  278 273 0  0 1 0";
  size_t at = text.find(lookAt);
  EXPECT_NE(at, std::string::npos);
  double f = std::stod(s);
  std::ostringstream eye;
  eye.precision(9);
  eye << "LookAt " << 278 * f << " " << 273 * f << " " << -800 * f << " " << 278 * f << " "
      << 273 * f << " 0 0 1 0";
  text.replace(at, lookAt.size(), eye.str());
  at = text.find("WorldBegin");
  text.insert(at + 10, "\nScale " + s + " " + s + " " + s + "\n");
  return text;
}

TEST(ExtremeScale, CornellBoxScaledDownAndUpRendersAsAtFullSize) {
  test::TestRenderOptions options;
  options.build.sppOverride = 4;
  double reference = meanOf(test::renderSceneText(test::cornellBoxText(16), options).film());
  ASSERT_GT(reference, 0.05);
  double worst = 0;
  for (const char* s : {"1e-7", "1e-6", "1e6"}) {
    double mean = meanOf(test::renderSceneText(scaledBox(s), options).film());
    EXPECT_NEAR(mean / reference, 1, 1e-4) << "scale " << s;
    worst = std::max(worst, std::abs(mean / reference - 1));
  }
  test::recordFigure("Cornell box scaled by 1e-7, 1e-6, 1e6: image mean within 1e-4 of scale 1's",
                     "largest |mean / mean at scale 1 - 1|: %.2g", worst);
}

// The lrt draft's absolute hither of 1e-3 leaves out the whole small box: said by a warning.
TEST(ExtremeScale, AHitherThatClipsEverythingIsReported) {
  std::string text = scaledBox("1e-7");
  size_t at = text.find("Camera \"perspective\"");
  ASSERT_NE(at, std::string::npos);
  text.insert(at + 20, " \"float hither\" [1e-3]");
  std::string warnings;
  test::TestRenderOptions options;
  options.build.sppOverride = 1;
  options.build.warn = [&](const FileLoc&, const std::string& message) { warnings += message; };
  double mean = meanOf(test::renderSceneText(text, options).film());
  EXPECT_EQ(mean, 0);
  EXPECT_NE(warnings.find("leaves out every object"), std::string::npos) << warnings;
  // Not said when something is in range.
  warnings.clear();
  test::renderSceneText(scaledBox("1e-7"), options);
  EXPECT_EQ(warnings.find("leaves out every object"), std::string::npos) << warnings;
  test::recordFigure("Cornell box scaled by 1e-7 with the lrt draft's hither 1e-3: a warning",
                     "image mean %g; warned", mean);
}

// The box moved (camera and world together) by 1e3 and 1e5 along each axis: the mean of the box
// at the origin within 2% (issue 15's criterion; spawning offsets follow the coordinates' error
// bounds), and no precision warning (556 mm across at 1e5: 46000 float steps).
std::string movedBox(double offset) {
  std::string text = test::cornellBoxText(16);
  const std::string lookAt = "LookAt 278 273 -800  278 273 0  0 1 0";
  size_t at = text.find(lookAt);
  EXPECT_NE(at, std::string::npos);
  std::ostringstream eye;
  eye.precision(12);
  eye << "LookAt " << 278 + offset << " " << 273 + offset << " " << -800 + offset << " "
      << 278 + offset << " " << 273 + offset << " " << offset << " 0 1 0";
  text.replace(at, lookAt.size(), eye.str());
  at = text.find("WorldBegin");
  std::ostringstream move;
  move.precision(12);
  move << "\nTranslate " << offset << " " << offset << " " << offset << "\n";
  text.insert(at + 10, move.str());
  return text;
}

TEST(ExtremeScale, CornellBoxFarFromTheOriginRendersAsAtTheOrigin) {
  test::TestRenderOptions options;
  options.build.sppOverride = 4;
  std::string warnings;
  options.build.warn = [&](const FileLoc&, const std::string& message) { warnings += message; };
  double reference = meanOf(test::renderSceneText(test::cornellBoxText(16), options).film());
  double worst = 0;
  for (double offset : {1e3, 1e5}) {
    double mean = meanOf(test::renderSceneText(movedBox(offset), options).film());
    EXPECT_NEAR(mean / reference, 1, 0.02) << "offset " << offset;
    worst = std::max(worst, std::abs(mean / reference - 1));
  }
  test::recordFigure("Cornell box moved by 1e3 and 1e5: image mean within 2% of the origin's",
                     "largest |mean / mean at the origin - 1|: %.2g", worst);
  EXPECT_EQ(warnings.find("floats are"), std::string::npos) << warnings;
}

// Where float cannot hold a shape (a unit sphere at 1e7, where floats are 1 apart), a warning
// names the statement and the precision there.
TEST(ExtremeScale, AShapeFloatsCannotResolveIsReported) {
  const std::string scene =
      "LookAt 1e7 0 -5 1e7 0 0 0 1 0\nCamera \"perspective\"\n"
      "Film \"image\" \"integer xresolution\" [8] \"integer yresolution\" [8]\n"
      "WorldBegin\nLightSource \"point\" \"point from\" [1e7 0 -5] \"rgb I\" [10 10 10]\n"
      "AttributeBegin\nTranslate 1e7 0 0\nShape \"sphere\"\nAttributeEnd\n"
      "Shape \"sphere\" \"float radius\" [2]\nWorldEnd\n";
  std::vector<std::pair<FileLoc, std::string>> warnings;
  test::TestRenderOptions options;
  options.build.sppOverride = 1;
  options.build.warn = [&](const FileLoc& loc, const std::string& message) {
    warnings.push_back({loc, message});
  };
  test::renderSceneText(scene, options);
  int precision = 0;
  for (const auto& [loc, message] : warnings)
    if (message.find("floats are") != std::string::npos) {
      ++precision;
      EXPECT_EQ(loc.line, 8) << message;  // the far sphere; the one at the origin is fine
      EXPECT_NE(message.find("shape 'sphere'"), std::string::npos) << message;
      EXPECT_NE(message.find("is 1e+07 from the origin, where floats are 1.19 apart"),
                std::string::npos)
          << message;
    }
  EXPECT_EQ(precision, 1);
  test::recordFigure("a unit sphere at 1e7: a warning naming it and the float spacing there",
                     "%d warning, at its statement", precision);
}

TEST(ExtremeScale, GeometryAtTheEndOfFloatRangeRendersFiniteUnderEveryAccelerator) {
  const std::string head =
      "LookAt 0 0 -5 0 0 0 0 1 0\nCamera \"perspective\" \"float fov\" [40]\n"
      "Film \"image\" \"integer xresolution\" [8] \"integer yresolution\" [8]\n"
      "Sampler \"random\" \"integer pixelsamples\" [2]\nWorldBegin\n"
      "LightSource \"point\" \"rgb I\" [10 10 10]\n";
  const std::string scenes[] = {
      head +
          "ObjectBegin \"a\"\nShape \"sphere\" \"float radius\" [3e38]\nObjectEnd\n"
          "ObjectInstance \"a\"\nWorldEnd\n",
      head +
          "Shape \"trianglemesh\" \"integer indices\" [0 1 2] \"point P\" "
          "[-3.4e38 -3.4e38 0 3.4e38 -3.4e38 0 0 3.4e38 0]\nWorldEnd\n"};
  for (const std::string& scene : scenes)
    for (const char* accel : {"embree", "bvh", "kdtree", "grid"}) {
      SCOPED_TRACE(accel);
      test::TestRenderOptions options;
      options.build.accelerator = accel;
      test::RenderedScene r = test::renderSceneText(scene, options);
      ImageBuffer image = r.film().image();
      for (float v : image.data) ASSERT_TRUE(std::isfinite(v));
    }
  test::recordFigure(
      "a sphere of radius 3e38 in an instance, a triangle at +-3.4e38: every pixel "
      "finite under the 4 accelerators",
      std::string("finite"));
}

}  // namespace
}  // namespace candela
