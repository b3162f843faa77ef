// A NaN or infinite radiance sample is never added to the film: it is counted and the first one
// (by row, column and sample index, so the same for any thread count) is reported, so that the
// bug can be reproduced with a crop window on that pixel. A point light of intensity 3e38 1e-4
// from a sphere gives infinite radiance where it overflows.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/render_scene.h"

namespace candela {
namespace {

const std::string kScene =
    "LookAt 0 0 -5 0 0 0 0 1 0\nCamera \"perspective\" \"float fov\" [40]\n"
    "Film \"image\" \"integer xresolution\" [16] \"integer yresolution\" [16]\n"
    "Sampler \"random\" \"integer pixelsamples\" [4]\nWorldBegin\n"
    "LightSource \"point\" \"rgb I\" [3e38 3e38 3e38] \"point from\" [0.3 0.2 -1.0001]\n"
    "Shape \"sphere\"\nWorldEnd\n";

RenderResult renderWith(int threads, std::optional<Bounds2f> crop = std::nullopt) {
  test::TestRenderOptions options;
  options.render.nThreads = threads;
  options.render.tileSize = 3;
  if (crop) options.build.cropWindow = *crop;
  test::RenderedScene r = test::renderSceneText(kScene, options);
  for (float v : r.film().image().data) EXPECT_TRUE(std::isfinite(v));
  return r.results.front();
}

TEST(NonFiniteSamples, AreDroppedCountedAndTheFirstIsTheSameForAnyThreadCount) {
  RenderResult one = renderWith(1), two = renderWith(2);
  ASSERT_GT(one.nonFiniteSamples, 0u);
  EXPECT_EQ(one.nonFiniteSamples, two.nonFiniteSamples);
  ASSERT_TRUE(one.firstNonFinite && two.firstNonFinite);
  const PixelSampleIndex f = *one.firstNonFinite;
  EXPECT_EQ(f.pixel.x, two.firstNonFinite->pixel.x);
  EXPECT_EQ(f.pixel.y, two.firstNonFinite->pixel.y);
  EXPECT_EQ(f.index, two.firstNonFinite->index);
  // The crop window on that pixel renders the same non-finite sample first.
  Bounds2f crop(Point2f(Float(f.pixel.x) / 16, Float(f.pixel.y) / 16),
                Point2f(Float(f.pixel.x + 1) / 16, Float(f.pixel.y + 1) / 16));
  RenderResult alone = renderWith(1, crop);
  ASSERT_TRUE(alone.firstNonFinite);
  EXPECT_EQ(alone.firstNonFinite->pixel.x, f.pixel.x);
  EXPECT_EQ(alone.firstNonFinite->pixel.y, f.pixel.y);
  EXPECT_EQ(alone.firstNonFinite->index, f.index);
  EXPECT_GE(alone.nonFiniteSamples, 1u);
  EXPECT_LT(alone.nonFiniteSamples, one.nonFiniteSamples);
}

}  // namespace
}  // namespace candela
