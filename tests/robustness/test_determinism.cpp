// The image is a pure function of (scene, samples per pixel, seed): the same bits for any
// thread count, tile size or crop window.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "support/render_scene.h"

namespace candela {
namespace {

std::string cornellBox(int resolution) { return test::cornellBoxText(resolution); }

test::RenderedScene render(const std::string& scene, int threads, int tile,
                           std::optional<Bounds2f> crop = std::nullopt, uint64_t seed = 7) {
  test::TestRenderOptions o;
  o.build.sppOverride = 4;
  o.build.seed = seed;
  o.build.cropWindow = crop;
  o.render.nThreads = threads;
  o.render.tileSize = tile;
  return test::renderSceneText(scene, o);
}

void expectSameBits(const ImageBuffer& a, const ImageBuffer& b) {
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  ASSERT_EQ(a.data.size(), b.data.size());
  EXPECT_EQ(0, std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)));
}

TEST(Determinism, SameBitsForAnyThreadCountAndTileSize) {
  std::string scene = cornellBox(48);
  ImageBuffer reference = render(scene, 1, 16).film().image();
  expectSameBits(reference, render(scene, 2, 16).film().image());
  expectSameBits(reference, render(scene, 2, 5).film().image());
  expectSameBits(reference, render(scene, 1, 64).film().image());
}

TEST(Determinism, CropWindowEqualsTheSameRegionOfTheFullImage) {
  std::string scene = cornellBox(48);
  ImageBuffer full = render(scene, 2, 16).film().image();
  Bounds2f crop(Point2f(0.2f, 0.35f), Point2f(0.7f, 0.9f));
  ImageBuffer part = render(scene, 2, 7, crop).film().image();
  ASSERT_GT(part.width, 0);
  ASSERT_GT(part.height, 0);
  EXPECT_LT(part.width, full.width);
  for (int y = 0; y < part.height; ++y)
    for (int x = 0; x < part.width; ++x)
      for (int c = 0; c < part.channelCount(); ++c)
        ASSERT_EQ(part.at(x, y, c), full.at(x + part.xOffset, y + part.yOffset, c))
            << "pixel " << x + part.xOffset << "," << y + part.yOffset;
}

TEST(Determinism, TheSeedChangesTheNoise) {
  std::string scene = cornellBox(16);
  ImageBuffer a = render(scene, 2, 16, std::nullopt, 1).film().image();
  ImageBuffer b = render(scene, 2, 16, std::nullopt, 2).film().image();
  EXPECT_NE(0, std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)));
}

TEST(CornellBox, RendersWithoutNaNOrInfAndBuildsNoUserGeometry) {
  auto r = render(cornellBox(64), 0, 16);
  ImageBuffer img = r.film().image();
  double sum = 0;
  for (float v : img.data) {
    ASSERT_TRUE(std::isfinite(v));
    ASSERT_GE(v, 0.f);
    sum += v;
  }
  EXPECT_GT(sum, 0);
  EXPECT_EQ(r.results.front().nonFiniteSamples, 0u);
  const BuildStats& stats = r.job().stats;
  EXPECT_EQ(stats.aggregate.counts.at("embree user geometries"), 0);
  EXPECT_GT(stats.aggregate.counts.at("embree triangle geometries"), 0);
  EXPECT_EQ(stats.shapesByKind.count("sphere"), 0u);
  EXPECT_EQ(stats.textures, 0);
}

}  // namespace
}  // namespace candela
