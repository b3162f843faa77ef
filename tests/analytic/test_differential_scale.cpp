// The camera ray differentials' scale (pbrt 3e §1.4.3): 1/sqrt(samples per pixel), and no less
// than pbrt-v3's 1/8 for scenes of its dialect, whose texture filter widths then stop shrinking
// past 64 samples per pixel (the pbrt-v3 conformance scenes' textures depend on it).
#include <gtest/gtest.h>

#include <string>

#include "renderers/sampler_renderer.h"
#include "support/render_scene.h"

using namespace candela;

namespace {

// Renders the distance between each camera ray's direction and its x offset ray's: the scale
// the renderer gave the differentials, times the camera's one-pixel step.
class DifferentialProbe : public SurfaceIntegrator {
 public:
  bool needsRayDifferentials() const override { return true; }
  Spectrum Li(const RayDifferential& ray, const Scene&, IntegratorContext&,
              Float* alpha) const override {
    *alpha = 1;
    return Spectrum(ray.hasDifferentials ? (ray.rxDirection - ray.d).length() : -1);
  }
};

std::string scene(const char* integratorStatement, int spp) {
  return "LookAt 0 0 5  0 0 0  0 1 0\n"
         "Camera \"perspective\" \"float fov\" [30]\n"
         "Film \"image\" \"integer xresolution\" [8] \"integer yresolution\" [8]\n"
         "Sampler \"random\" \"integer pixelsamples\" [" +
         std::to_string(spp) + "]\n" + integratorStatement +
         "\nWorldBegin\nShape \"sphere\" \"float radius\" [1]\nWorldEnd\n";
}

// The film's mean over the pixels: the probe's mean offset.
double meanOffset(const char* integratorStatement, int spp, Float minScale) {
  test::RenderedScene r = test::buildSceneText(scene(integratorStatement, spp));
  RenderJob& job = r.job();
  DifferentialProbe probe;
  SamplerRenderer renderer(*job.camera, *job.sampler, probe, nullptr, minScale);
  renderer.render(*job.scene, *job.film, RenderOptions{1, 16, true});
  double sum = 0;
  int n = 0;
  Bounds2i b = job.film->pixelBounds();
  for (int y = b.pMin.y; y < b.pMax.y; ++y)
    for (int x = b.pMin.x; x < b.pMax.x; ++x, ++n) sum += job.film->pixelValue(Point2i(x, y))[0];
  return sum / n;
}

}  // namespace

TEST(DifferentialScale, IsOneOverTheRootOfTheSampleCountAndNoLessThanTheFloor) {
  const char* v2 = "SurfaceIntegrator \"directlighting\"";
  // Below 64 samples the floor of 1/8 changes nothing: the same bits.
  EXPECT_EQ(meanOffset(v2, 16, 0), meanOffset(v2, 16, 0.125f));
  // At 256 samples 1/16 without it and 1/8 with it: twice the offset (the offsets are small and
  // the camera's step nearly linear, so the ratio is 2 to a few parts in a million).
  double unscaled = meanOffset(v2, 256, 0), floored = meanOffset(v2, 256, 0.125f);
  EXPECT_GT(unscaled, 0);
  EXPECT_NEAR(floored / unscaled, 2.0, 1e-4);
  // And with it, 256 samples have the footprint of 64.
  EXPECT_NEAR(floored / meanOffset(v2, 64, 0), 1.0, 1e-4);
}

TEST(DifferentialScale, TheFloorIsPbrtV3sSamplerIntegratorsOnly) {
  test::RenderedScene v2 = test::buildSceneText(scene("SurfaceIntegrator \"path\"", 4));
  EXPECT_EQ(v2.job().minDifferentialScale, 0);
  test::RenderedScene v3 = test::buildSceneText(scene("Integrator \"path\"", 4));
  EXPECT_EQ(v3.job().minDifferentialScale, Float(0.125));
  // pbrt-v3's BDPT has no floor: 1/sqrt(spp) alone.
  test::RenderedScene bdpt = test::buildSceneText(scene("Integrator \"bdpt\"", 4));
  EXPECT_EQ(bdpt.job().minDifferentialScale, 0);
  BuildOptions asV2;
  asV2.materialModels.dialect = SceneDialect::PbrtV2;
  test::RenderedScene forced = test::buildSceneText(scene("Integrator \"path\"", 4), asV2);
  EXPECT_EQ(forced.job().minDifferentialScale, 0);
}
