// Splatting integrators keep the image a pure function of (scene, spp, seed): a test integrator
// that splats every sample's light to a film position drawn from the sample (values over fifteen
// decades, as light tracing produces) renders the same bits for 1 and 2 threads and tile sizes 8,
// 16 and 5, and a crop window renders the same bits as that region of the full image, including
// light splatted from pixels outside the crop.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "film/splat_buffer.h"
#include "support/render_scene.h"

namespace candela {
namespace {

class RandomSplatter : public PixelSampleIntegrator {
 public:
  explicit RandomSplatter(Point2i res) : res_(res) {}
  PixelLight pixelLight() const override { return PixelLight::Splatted; }
  // As bdpt, the base's loop then takes every pixel of the full image, its splats landing anywhere.
  Spectrum Li(const RayDifferential&, const Scene&, IntegratorContext& ctx,
              Float* alpha) const override {
    *alpha = 1;
    for (int i = 0; i < 3; ++i) {
      Point2f u = ctx.sampler.get2D();
      Float v = std::pow(Float(10), -9 + 15 * ctx.sampler.get1D());
      ctx.splats->add(Point2f(u.x * res_.x, u.y * res_.y), Spectrum(v, 2 * v, 0.5f * v));
    }
    return Spectrum(ctx.sampler.get1D());
  }

 private:
  Point2i res_;
};

const char* kScene = R"(
Film "image" "integer xresolution" [24] "integer yresolution" [16]
PixelFilter "gaussian"
Sampler "random" "integer pixelsamples" [4]
Camera "perspective"
WorldBegin
WorldEnd
)";

ImageBuffer render(int threads, int tile, std::optional<Bounds2f> crop = std::nullopt) {
  BuildOptions build;
  build.seed = 3;
  build.cropWindow = crop;
  test::RenderedScene r = test::buildSceneText(kScene, build);
  RandomSplatter integrator(r.job().film->fullResolution());
  RenderOptions ro;
  ro.nThreads = threads;
  ro.tileSize = tile;
  ro.quiet = true;
  integrator.renderSamples({*r.job().scene, *r.job().camera, *r.job().sampler}, *r.job().film, ro);
  EXPECT_EQ(r.job().film->splats()->refused(), 0u);
  return r.job().film->image();
}

bool sameBits(const float* a, const float* b, size_t n) {
  return std::memcmp(a, b, n * sizeof(float)) == 0;
}

TEST(SplatDeterminism, SameBitsForAnyThreadCountAndTileSize) {
  ImageBuffer ref = render(1, 16);
  for (auto [threads, tile] : {std::pair{2, 16}, std::pair{2, 8}, std::pair{2, 5}}) {
    ImageBuffer other = render(threads, tile);
    ASSERT_EQ(other.data.size(), ref.data.size());
    EXPECT_TRUE(sameBits(ref.data.data(), other.data.data(), ref.data.size()))
        << threads << " threads, tile " << tile;
  }
}

TEST(SplatDeterminism, CropEqualsTheSameRegionOfTheFullImage) {
  ImageBuffer full = render(2, 8);
  ImageBuffer crop = render(2, 8, Bounds2f(Point2f(0.25f, 0.5f), Point2f(0.75f, 1)));
  ASSERT_EQ(crop.width, 12);
  ASSERT_EQ(crop.height, 8);
  int channels = int(full.channels.size());
  for (int y = 0; y < crop.height; ++y)
    for (int x = 0; x < crop.width; ++x)
      for (int c = 0; c < channels; ++c)
        ASSERT_EQ(crop.at(x, y, c), full.at(x + crop.xOffset, y + crop.yOffset, c))
            << x << " " << y << " " << c;
}

}  // namespace
}  // namespace candela
