// pbrt-v2's bunny example (measured car paint, mystique.brdf, irregular samples) through the
// renderer: with pbrt 2e §8.6's radius search the highlights are broad, so isolated pixels far
// brighter than their neighbourhood carry little of the bunny's light. A lookup too local for
// the data's few samples near the mirror direction (candela's earlier 8-nearest interpolation)
// makes sub-pixel highlights that sparkle: a fifth of the light was in such pixels.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "support/render_scene.h"

namespace candela {
namespace {

namespace fs = std::filesystem;

fs::path pbrtV2Dir() { return fs::path(CANDELA_SHARED_SCENES_DIR) / "pbrt-v2"; }

// bunny.pbrt at 160 x 120 with 8 samples per pixel, its files named by absolute paths, and the
// ground black so that only the bunny is lit in the image.
std::string bunnyText() {
  std::ifstream in(pbrtV2Dir() / "bunny.pbrt");
  std::stringstream ss;
  ss << in.rdbuf();
  std::string s = ss.str();
  auto replace = [&](const std::string& from, const std::string& to) {
    size_t at = s.find(from);
    if (at == std::string::npos) throw std::logic_error("bunny.pbrt has no '" + from + "'");
    s.replace(at, from.size(), to);
  };
  replace("Film \"image\"",
          "Film \"image\" \"integer xresolution\" [160] "
          "\"integer yresolution\" [120]\n"
          "Sampler \"lowdiscrepancy\" \"integer pixelsamples\" [8]");
  // Built by appending: GCC 12 warns falsely (-Wrestrict) on "\"" + std::string.
  auto quotedDir = [](const char* sub) {
    std::string q = "\"";
    q.append((pbrtV2Dir() / sub).string()).append("/");
    return q;
  };
  replace("\"brdfs/", quotedDir("brdfs"));
  replace("\"geometry/", quotedDir("geometry"));
  replace("\"color Kd\" [.4 .42 .4]", "\"color Kd\" [0 0 0]");
  return s;
}

float luminance(const ImageBuffer& img, int x, int y) {
  return 0.2126f * img.at(x, y, 0) + 0.7152f * img.at(x, y, 1) + 0.0722f * img.at(x, y, 2);
}

TEST(MeasuredBrdfRenders, BunnyHighlightsDoNotSparkle) {
  if (!fs::exists(pbrtV2Dir() / "bunny.pbrt") || !fs::exists(pbrtV2Dir() / "brdfs"))
    GTEST_SKIP() << "pbrt-v2 scenes not found in " << pbrtV2Dir();
  test::TestRenderOptions o;
  o.build.nThreads = 2;
  o.render.nThreads = 2;
  ImageBuffer img = test::renderSceneText(bunnyText(), o).film().image();
  // An outlier: brighter than 5 times the median of its 3 x 3 neighbourhood (itself included),
  // where that median is lit. Measured fractions of the lit luminance in outliers: 1-2% here (the
  // light's and the pixel's sampling noise, falling with more samples), 12-19% with the
  // 8-nearest interpolation.
  double lit = 0, inOutliers = 0;
  int litPixels = 0;
  for (int y = 1; y + 1 < img.height; ++y)
    for (int x = 1; x + 1 < img.width; ++x) {
      float v = luminance(img, x, y), n[9];
      lit += v;
      litPixels += v > 0;
      int k = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) n[k++] = luminance(img, x + dx, y + dy);
      std::nth_element(n, n + 4, n + 9);
      if (n[4] > 0 && v > 5 * n[4]) inOutliers += v;
    }
  std::printf("bunny: %.2f%% of the lit luminance in outlier pixels (%d lit pixels)\n",
              100 * inOutliers / lit, litPixels);
  ASSERT_GT(litPixels, 2000);  // the bunny covers about a fifth of the image
  EXPECT_LT(inOutliers, 0.05 * lit);
}

}  // namespace
}  // namespace candela
