// The irradiance cache's prepass and render are a function of (scene, spp, seed): the same bits
// for 1 or 2 threads, any tile size, and a crop window (the prepass covers the whole image).
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <sstream>

#include "integrators/irradiance/irradiance_cache_integrator.h"
#include "support/render_scene.h"

namespace candela {
namespace {

// The Cornell box at low resolution, with a cheap cache; minpixelspacing below a pixel so that
// the last rounds of the prepass place samples, where an order dependence would show.
std::string cornellBoxCache(int resolution) {
  return test::cornellBoxText(resolution,
                              "SurfaceIntegrator \"irradiancecache\" \"integer nsamples\" [32] "
                              "\"float minpixelspacing\" [0.7] \"float maxpixelspacing\" [6]");
}

test::RenderedScene render(const std::string& scene, int threads, int tile,
                           std::optional<Bounds2f> crop = std::nullopt) {
  test::TestRenderOptions o;
  o.build.sppOverride = 2;
  o.build.seed = 11;
  o.build.cropWindow = crop;
  o.render.nThreads = threads;
  o.render.tileSize = tile;
  return test::renderSceneText(scene, o);
}

const IrradianceOctree& cacheOf(test::RenderedScene& r) {
  auto* ic = dynamic_cast<const IrradianceCacheIntegrator*>(r.job().integrator.get());
  EXPECT_NE(ic, nullptr);
  return *ic->cache();
}

void expectSameBits(const ImageBuffer& a, const ImageBuffer& b) {
  ASSERT_EQ(a.data.size(), b.data.size());
  EXPECT_EQ(0, std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)));
}

void expectSameCache(const IrradianceOctree& a, const IrradianceOctree& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    const IrradianceSample &x = a.samples()[i], &y = b.samples()[i];
    ASSERT_EQ(0, std::memcmp(&x, &y, sizeof(IrradianceSample))) << "sample " << i;
  }
}

TEST(IrradianceCacheDeterminism, SameCacheAndBitsForThreadsAndTileSizes) {
  std::string scene = cornellBoxCache(24);
  auto reference = render(scene, 1, 16);
  EXPECT_GT(cacheOf(reference).size(), 20u);
  for (auto [threads, tile] : {std::pair{2, 16}, std::pair{1, 8}, std::pair{2, 8}}) {
    SCOPED_TRACE(std::to_string(threads) + " threads, tile " + std::to_string(tile));
    auto r = render(scene, threads, tile);
    expectSameCache(cacheOf(reference), cacheOf(r));
    expectSameBits(reference.film().image(), r.film().image());
  }
}

TEST(IrradianceCacheDeterminism, CropWindowEqualsTheSameRegionOfTheFullImage) {
  std::string scene = cornellBoxCache(24);
  auto full = render(scene, 2, 16);
  ImageBuffer fullImage = full.film().image();
  auto cropped = render(scene, 2, 8, Bounds2f(Point2f(0.3f, 0.5f), Point2f(0.8f, 0.95f)));
  expectSameCache(cacheOf(full), cacheOf(cropped));
  ImageBuffer part = cropped.film().image();
  ASSERT_GT(part.width, 0);
  EXPECT_LT(part.width, fullImage.width);
  for (int y = 0; y < part.height; ++y)
    for (int x = 0; x < part.width; ++x)
      for (int c = 0; c < part.channelCount(); ++c)
        ASSERT_EQ(part.at(x, y, c), fullImage.at(x + part.xOffset, y + part.yOffset, c))
            << "pixel " << x + part.xOffset << "," << y + part.yOffset;
}

}  // namespace
}  // namespace candela

namespace candela {
namespace {

// --quick takes a sixteenth of every estimate's hemisphere samples (pbrt-v2's rule), at least
// one, and keeps nfilter below the count.
TEST(IrradianceCacheQuick, QuickTakesASixteenthOfTheSamples) {
  auto settingsOf = [](const std::string& params, bool quick) {
    BuildOptions o;
    o.quick = quick;
    auto r = test::buildSceneText(
        test::cornellBoxText(8, "SurfaceIntegrator \"irradiancecache\" " + params), o);
    auto* ic = dynamic_cast<const IrradianceCacheIntegrator*>(r.job().integrator.get());
    EXPECT_NE(ic, nullptr);
    return ic ? ic->settings() : IrradianceCacheSettings{};
  };
  EXPECT_EQ(settingsOf("\"integer nsamples\" [640]", false).nSamples, 640);
  EXPECT_EQ(settingsOf("\"integer nsamples\" [640]", true).nSamples, 40);
  EXPECT_EQ(settingsOf("\"integer nsamples\" [8]", true).nSamples, 1);
  IrradianceCacheSettings s =
      settingsOf("\"integer nsamples\" [64] \"integer nfilter\" [10]", true);
  EXPECT_EQ(s.nSamples, 4);
  EXPECT_EQ(s.nFilter, 3);
}

}  // namespace
}  // namespace candela
