// SPPM's image is a pure function of (scene, iterations, seed): the same bits for any thread count
// and tile size, and a crop window renders its pixels exactly as the full image does (every
// photon is shot whatever the crop). Its progressive passes report after 1, 2, 4, ... iterations
// and the last, and stop when asked.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "support/photon_scenes.h"
#include "support/render_scene.h"

namespace candela {
namespace {

// photons: "integer photonsperiteration" or, when 0, the default (the full image's pixel count).
std::string room(int iterations, int photons = 3000) {
  std::string count = photons ? " \"integer photonsperiteration\" [" + std::to_string(photons) + "]"
                              : std::string();
  return test::causticRoom(16, 1,
                           "\"sppm\" \"integer numiterations\" [" + std::to_string(iterations) +
                               "] \"float radius\" [0.15]" + count);
}

ImageBuffer render(int iterations, int threads, int tile, std::optional<Bounds2f> crop = {},
                   int photons = 3000) {
  test::TestRenderOptions o;
  o.build.seed = 5;
  o.build.nThreads = threads;
  o.build.cropWindow = crop;
  o.render.nThreads = threads;
  o.render.tileSize = tile;
  return test::renderSceneText(room(iterations, photons), o).film().image();
}

bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

TEST(SppmDeterminism, SameBitsForThreadsTilesAndCrop) {
  ImageBuffer one = render(5, 1, 16);
  ImageBuffer two = render(5, 2, 5);
  EXPECT_TRUE(sameBits(one.data, two.data));
  double sum = 0;
  for (float v : one.data) sum += v;
  EXPECT_GT(sum, 0);  // not trivially equal

  // x in [4, 12), y in [8, 16) of the 16 x 16 image; also with the default photon count, which
  // follows the full image, not the crop.
  for (int photons : {3000, 0}) {
    SCOPED_TRACE(photons);
    ImageBuffer full = photons ? one : render(5, 1, 16, {}, photons);
    ImageBuffer crop = render(5, 2, 3, Bounds2f(Point2f(0.25f, 0.5f), Point2f(0.75f, 1)), photons);
    ASSERT_EQ(crop.width, 8);
    ASSERT_EQ(crop.height, 8);
    const int nc = full.channelCount();
    ASSERT_EQ(crop.channelCount(), nc);
    std::vector<float> region;
    for (int y = 8; y < 16; ++y)
      for (int x = 4; x < 12; ++x)
        for (int c = 0; c < nc; ++c) region.push_back(full.data[(size_t(y) * 16 + x) * nc + c]);
    EXPECT_TRUE(sameBits(region, crop.data));
  }

  // Another seed is another image.
  test::TestRenderOptions o;
  o.build.seed = 6;
  EXPECT_FALSE(sameBits(test::renderSceneText(room(5), o).film().image().data, one.data));
}

struct Passes {
  std::vector<int> spp;
  ProgressiveResult result;
  ImageBuffer image;
};

Passes progressive(int iterations, int stopAt, int sppOverride = 0) {
  BuildOptions b;
  b.seed = 5;
  b.sppOverride = sppOverride;
  auto built = test::buildSceneText(room(iterations), b);
  Passes p;
  ProgressiveOptions po;
  po.render.quiet = true;
  po.afterPass = [&](const PassReport& r) {
    p.spp.push_back(r.spp);
    EXPECT_EQ(r.pass + 1, int(p.spp.size()));
    return stopAt == 0 || r.spp < stopAt;
  };
  p.result = renderJob(built.job(), po);
  p.image = built.film().image();
  return p;
}

TEST(SppmProgressive, ReportsAfterDoublingIterationsAndTheLast) {
  Passes p = progressive(6, 0);
  EXPECT_EQ(p.spp, (std::vector<int>{1, 2, 4, 6}));
  EXPECT_EQ(p.result.spp, 6);
  EXPECT_EQ(p.result.passes, 4);
  EXPECT_EQ(p.result.reason, StopReason::Completed);
  // The film holds the estimate, replaced at each pass: the same bits as a plain render.
  EXPECT_TRUE(sameBits(p.image.data, render(6, 2, 16).data));
}

TEST(SppmProgressive, StopsWhenAskedWithTheImageSoFar) {
  Passes p = progressive(16, 2);
  EXPECT_EQ(p.spp, (std::vector<int>{1, 2}));
  EXPECT_EQ(p.result.spp, 2);
  EXPECT_EQ(p.result.reason, StopReason::TargetError);
  // Iteration k does not depend on how many follow: stopping at 2 is a 2-iteration render.
  EXPECT_TRUE(sameBits(p.image.data, render(2, 1, 16).data));
}

TEST(SppmProgressive, SppOverrideSetsTheIterations) {
  Passes p = progressive(64, 0, 3);
  EXPECT_EQ(p.spp, (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(p.result.spp, 3);
}

}  // namespace
}  // namespace candela
