// Texture antialiasing end to end (lrt draft §11.2; seed inventory §25): a plane of checks far
// finer than the pixels must render as the plane with their mean reflectance, which needs the
// camera's ray differentials to reach the textures' filters. The checkerboard's closed form
// gives exactly the mean; the EWA MIP map of a fine checked image the mean within 1%; point
// sampling does not (which shows the comparison can fail).
#include <gtest/gtest.h>

#include <string>

#include "support/render_scene.h"

namespace candela {
namespace {

// A 2 x 2 quad facing the camera, filling the 32 x 32 image, lit by a distant light from behind
// the camera; Kd is the given material parameter.
std::string quadScene(const std::string& textures, const std::string& kd) {
  return "LookAt 0 0 -3  0 0 0  0 1 0\n"
         "Camera \"perspective\" \"float fov\" [30]\n"
         "Film \"image\" \"integer xresolution\" [32] \"integer yresolution\" [32]\n"
         "Sampler \"stratified\" \"integer xsamples\" [2] \"integer ysamples\" [2]\n"
         "SurfaceIntegrator \"directlighting\"\n"
         "WorldBegin\n"
         "LightSource \"distant\" \"point from\" [0 0 -1] \"point to\" [0 0 0] "
         "\"rgb L\" [3 3 3]\n" +
         textures + "Material \"matte\" " + kd +
         "\n"
         "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3]\n"
         "  \"point P\" [-1 -1 0  1 -1 0  1 1 0  -1 1 0] \"float uv\" [0 0 1 0 1 1 0 1]\n"
         "WorldEnd\n";
}

// Mean over pixels of |a - b| / b, red channel.
double meanRelativeDifference(const Film& a, const Film& b) {
  double sum = 0;
  int n = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      double va = a.pixelValue(Point2i(x, y))[0], vb = b.pixelValue(Point2i(x, y))[0];
      EXPECT_GT(vb, 0);
      sum += std::abs(va - vb) / vb;
      ++n;
    }
  return sum / n;
}

std::string checks(const std::string& aamode) {
  // 512 checks across the quad: about 16 per pixel.
  return "Texture \"checks\" \"spectrum\" \"checkerboard\" \"float uscale\" [512] "
         "\"float vscale\" [512] \"rgb tex1\" [1 1 1] \"rgb tex2\" [0 0 0] \"string aamode\" \"" +
         aamode + "\"\n";
}

TEST(TextureAntialiasing, ClosedFormCheckerboardRendersAsItsMean) {
  auto grey = test::renderSceneText(quadScene("", "\"rgb Kd\" [.5 .5 .5]"));
  auto closed = test::renderSceneText(quadScene(checks("closedform"), "\"texture Kd\" \"checks\""));
  // Every footprint spans many checks, so Kd is exactly 0.5 everywhere.
  EXPECT_LT(meanRelativeDifference(closed.film(), grey.film()), 1e-6);
  auto none = test::renderSceneText(quadScene(checks("none"), "\"texture Kd\" \"checks\""));
  EXPECT_GT(meanRelativeDifference(none.film(), grey.film()), 0.05);
}

TEST(TextureAntialiasing, EwaImageMapOfFineChecksRendersAsItsMean) {
  // A 64 x 64 image of one-texel checks, tiled 8 times: 512 texels across the quad.
  test::TestRenderOptions options;
  int loads = 0;
  options.build.loadImage = [&](const std::string&, const std::string&) {
    ++loads;
    ImageBuffer img(64, 64, {"R", "G", "B"});
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x)
        for (int c = 0; c < 3; ++c) img.at(x, y, c) = float((x + y) & 1);
    return img;
  };
  auto grey = test::renderSceneText(quadScene("", "\"rgb Kd\" [.5 .5 .5]"));
  for (const char* filter : {"false", "true"}) {
    std::string tex =
        "Texture \"img\" \"spectrum\" \"imagemap\" \"string filename\" \"checks.png\" "
        "\"float uscale\" [8] \"float vscale\" [8] \"bool trilinear\" \"" +
        std::string(filter) + "\"\n";
    auto img = test::renderSceneText(quadScene(tex, "\"texture Kd\" \"img\""), options);
    EXPECT_LT(meanRelativeDifference(img.film(), grey.film()), 0.01) << "trilinear " << filter;
  }
  EXPECT_EQ(loads, 2);  // once per render job
}

}  // namespace
}  // namespace candela
