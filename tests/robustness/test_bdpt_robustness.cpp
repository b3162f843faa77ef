// Bidirectional path tracing: the image is the same bits for 1 and 2 threads and tile sizes 8 and
// 16, and a crop window renders the same bits as that region of the full image (light subpaths of
// pixels outside the crop still splat into it); scene errors are located: a negative maxdepth, an
// unknown lightsamplestrategy (or lightsampler), a camera without importance (named in the
// message).
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "support/render_scene.h"

namespace candela {
namespace {

std::string cornellBox(const std::string& integrator, int res) {
  return test::cornellBoxText(res, integrator);
}

ImageBuffer render(const std::string& scene, int threads, int tile,
                   std::optional<Bounds2f> crop = std::nullopt) {
  test::TestRenderOptions o;
  o.build.sppOverride = 4;
  o.build.seed = 11;
  o.build.cropWindow = crop;
  o.render.nThreads = threads;
  o.render.tileSize = tile;
  return test::renderSceneText(scene, o).film().image();
}

bool sameBits(const ImageBuffer& a, const ImageBuffer& b) {
  return a.data.size() == b.data.size() &&
         std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)) == 0;
}

const char* kBdpt = "Integrator \"bdpt\" \"integer maxdepth\" [5]";

TEST(BdptDeterminism, SameBitsForThreadsAndTileSizes) {
  std::string scene = cornellBox(kBdpt, 24);
  ImageBuffer ref = render(scene, 1, 16);
  EXPECT_TRUE(sameBits(ref, render(scene, 2, 16)));
  EXPECT_TRUE(sameBits(ref, render(scene, 2, 8)));
  EXPECT_TRUE(sameBits(ref, render(scene, 1, 8)));
}

TEST(BdptDeterminism, CropWindowEqualsTheSameRegionOfTheFullImage) {
  std::string scene = cornellBox(kBdpt, 24);
  ImageBuffer full = render(scene, 2, 8);
  ImageBuffer crop = render(scene, 2, 16, Bounds2f(Point2f(0.25f, 0.5f), Point2f(0.75f, 0.875f)));
  ASSERT_EQ(crop.width, 12);
  ASSERT_EQ(crop.height, 9);
  bool anyLight = false;
  for (int y = 0; y < crop.height; ++y)
    for (int x = 0; x < crop.width; ++x)
      for (int c = 0; c < crop.channelCount(); ++c) {
        float v = crop.at(x, y, c);
        anyLight |= v > 0;
        ASSERT_EQ(v, full.at(x + crop.xOffset, y + crop.yOffset, c)) << x << " " << y << " " << c;
      }
  EXPECT_TRUE(anyLight);
}

// The pbrt-v2/lrt name renders the same image as pbrt-v3's.
TEST(BdptDeterminism, BidirectionalIsBdpt) {
  EXPECT_TRUE(
      sameBits(render(cornellBox(kBdpt, 8), 1, 16),
               render(cornellBox("SurfaceIntegrator \"bidirectional\" \"integer maxdepth\" [5]", 8),
                      1, 16)));
}

void expectSceneError(const std::string& scene, const std::string& where, const std::string& what) {
  try {
    test::buildSceneText(scene);
    FAIL() << "no error for " << what;
  } catch (const SceneError& e) {
    std::string m = e.what();
    EXPECT_NE(m.find(where), std::string::npos) << m;
    EXPECT_NE(m.find(what), std::string::npos) << m;
  }
}

const char* kWorld = "WorldBegin\nLightSource \"point\"\nShape \"sphere\"\nWorldEnd\n";

TEST(BdptErrors, NegativeMaxDepthIsLocated) {
  expectSceneError(std::string("Camera \"perspective\"\n") +
                       "Integrator \"bdpt\"\n  \"integer maxdepth\" [-1]\n" + kWorld,
                   ":3:", "\"maxdepth\" must be at least 0 (got -1)");
  expectSceneError(std::string("Camera \"perspective\"\n") +
                       "SurfaceIntegrator \"bidirectional\" \"integer maxdepth\" [-2]\n" + kWorld,
                   ":2:", "\"maxdepth\" must be at least 0 (got -2)");
}

TEST(BdptErrors, UnknownLightSamplerIsLocated) {
  expectSceneError(
      std::string("Camera \"perspective\"\n") +
          "Integrator \"bdpt\" \"string lightsampler\" \"tree\"\n" + kWorld,
      ":2:", "\"lightsampler\" must be one of uniform, power, spatial, bvh (got \"tree\")");
  expectSceneError(
      std::string("Camera \"perspective\"\n") +
          "Integrator \"bdpt\"\n  \"string lightsamplestrategy\" \"tree\"\n" + kWorld,
      ":3:", "\"lightsamplestrategy\" must be one of uniform, power, spatial, bvh (got \"tree\")");
}

TEST(BdptErrors, CameraWithoutImportanceIsNamed) {
  for (const char* cam : {"orthographic", "environment"})
    expectSceneError(std::string("Camera \"") + cam + "\"\nIntegrator \"bdpt\"\n" + kWorld,
                     ":2:", std::string("'") + cam + "' camera does not support");
}

}  // namespace
}  // namespace candela
