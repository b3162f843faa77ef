// The adaptive sampler through the renderer: extra samples only where a pixel's first samples
// disagree (pbrt-v2's shape-id rule here: a silhouette), and still the same bits for any thread
// count or tile size.
#include <gtest/gtest.h>

#include "support/render_scene.h"

namespace candela {
namespace {

const char* kScene =
    "LookAt 0 0 -5  0 0 0  0 1 0\n"
    "Camera \"perspective\" \"float fov\" [40]\n"
    "Film \"image\" \"integer xresolution\" [48] \"integer yresolution\" [48]\n"
    "Sampler \"adaptive\" \"integer minsamples\" [4] \"integer maxsamples\" [32]"
    " \"string method\" \"shapeid\"\n"
    "SurfaceIntegrator \"directlighting\"\n"
    "WorldBegin\n"
    "LightSource \"point\" \"point from\" [0 0 -5] \"rgb I\" [10 10 10]\n"
    "Shape \"sphere\"\n"
    "WorldEnd\n";

TEST(AdaptiveRendering, ExtraSamplesOnlyOnTheSilhouette) {
  test::TestRenderOptions o;
  o.render.nThreads = 1;
  auto r = test::renderSceneText(kScene, o);
  const Film& film = r.film();
  EXPECT_EQ(film.pixelSampleCount(Point2i(24, 24)), 4);  // inside the sphere
  EXPECT_EQ(film.pixelSampleCount(Point2i(1, 1)), 4);    // background
  long full = 0, total = 0;
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 48; ++x) {
      long n = film.pixelSampleCount(Point2i(x, y));
      EXPECT_TRUE(n == 4 || n == 32) << n;
      full += n == 32;
      total += n;
    }
  EXPECT_GT(full, 20);                 // the silhouette's pixels
  EXPECT_LT(total, 48 * 48 * 32 / 4);  // far fewer than every pixel at maxsamples
  EXPECT_EQ(uint64_t(total), r.results.front().samples);

  test::TestRenderOptions o2;
  o2.render.nThreads = 2;
  o2.render.tileSize = 5;
  ImageBuffer a = film.image(), b = test::renderSceneText(kScene, o2).film().image();
  ASSERT_EQ(a.data.size(), b.data.size());
  EXPECT_EQ(0, std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)));
}

}  // namespace
}  // namespace candela
