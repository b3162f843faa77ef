// The camera ray differentials' scale (pbrt 3e §1.4.3): 1/sqrt(samples per pixel), and no less
// than pbrt-v3's 1/8 for scenes of its dialect rendered by its sampler integrators, whose texture
// filter widths then stop shrinking past 64 samples per pixel (the pbrt-v3 conformance scenes'
// textures depend on it); SPPM's scale is 1/sqrt(iterations), as pbrt-v3's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <string>
#include <vector>

#include "integrators/pixel_sample_integrator.h"
#include "support/render_scene.h"

using namespace candela;

namespace {

// Renders the distance between each camera ray's direction and its x offset ray's: the scale
// the renderer gave the differentials, times the camera's one-pixel step.
class DifferentialProbe : public PixelSampleIntegrator {
 public:
  RenderResult renderSamples(const RenderInputs& in, Film& film,
                             const RenderOptions& options) override {
    SampleLoop loop = sampleLoop(in, film);
    loop.rayDifferentials = true;  // whatever the scene's textures
    return renderPixelSamples(in, film, options, loop);
  }
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
  probe.setMinDifferentialScale(minScale);
  probe.renderSamples({*job.scene, *job.camera, *job.sampler}, *job.film,
                      RenderOptions{1, 16, true});
  std::vector<Spectrum> pixels = test::pixelValues(*job.film);
  double sum = 0;
  for (const Spectrum& v : pixels) sum += v[0];
  return sum / double(pixels.size());
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

// The floor the build gave the job's pixel-sample integrator.
Float floorOf(test::RenderedScene& r) {
  return dynamic_cast<const PixelSampleIntegrator&>(*r.job().integrator).minDifferentialScale();
}

TEST(DifferentialScale, TheFloorIsPbrtV3sSamplerIntegratorsOnly) {
  test::RenderedScene v2 = test::buildSceneText(scene("SurfaceIntegrator \"path\"", 4));
  EXPECT_EQ(floorOf(v2), 0);
  test::RenderedScene v3 = test::buildSceneText(scene("Integrator \"path\"", 4));
  EXPECT_EQ(floorOf(v3), Float(0.125));
  // pbrt-v3's BDPT has no floor: 1/sqrt(spp) alone.
  test::RenderedScene bdpt = test::buildSceneText(scene("Integrator \"bdpt\"", 4));
  EXPECT_EQ(floorOf(bdpt), 0);
  BuildOptions asV2;
  asV2.compatibility.dialect = SceneDialect::PbrtV2;
  test::RenderedScene forced = test::buildSceneText(scene("Integrator \"path\"", 4), asV2);
  EXPECT_EQ(floorOf(forced), 0);
}

namespace {

// A plane filling an orthographic view, lit head-on by a distant light of radiance pi so that a
// pixel shows its albedo Kd exactly; Kd = c^2, c a closed-form checkerboard of 0 and 1 with 3
// checks a pixel (u runs 1/8 a pixel, uscale 24). The checkerboard filters over half the
// footprint each way (ds = 1.5 at the full pixel), and wider than a check it is the mean, 0.5:
// c^2 is then 0.25 everywhere. At footprint scale 1/8 (ds = 3/16) c is 0 or 1 away from the
// checks' edges and ramps across them: over the plane c^2 averages 0.3906 (by quadrature of the
// closed form; 0.2778 at scale 1/4 ... 0.25 from scale 2/3 up).
std::string checkSquaresUnderSppm(int iterations) {
  return "LookAt 0 0 5  0 0 0  0 1 0\nCamera \"orthographic\"\n"
         "Film \"image\" \"integer xresolution\" [8] \"integer yresolution\" [8]\n"
         "Integrator \"sppm\" \"integer numiterations\" [" +
         std::to_string(iterations) +
         "]\nWorldBegin\n"
         "LightSource \"distant\" \"point from\" [0 0 5] \"point to\" [0 0 0] "
         "\"rgb L\" [3.14159265 3.14159265 3.14159265]\n"
         "Texture \"c\" \"spectrum\" \"checkerboard\" \"float uscale\" [24] \"float vscale\" [24] "
         "\"rgb tex1\" [0 0 0] \"rgb tex2\" [1 1 1]\n"
         "Texture \"c2\" \"spectrum\" \"scale\" \"texture tex1\" \"c\" \"texture tex2\" \"c\"\n"
         "Material \"matte\" \"texture Kd\" \"c2\"\n"
         "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] "
         "\"point P\" [-1 -1 0  1 -1 0  1 1 0  -1 1 0] \"float uv\" [0 0  1 0  1 1  0 1]\n"
         "WorldEnd\n";
}

}  // namespace

// pbrt-v3's SPPM scales camera ray differentials by 1/sqrt(iterations) (pbrt 3e §16.2.2): one
// iteration filters each check over a whole pixel, 64 over an eighth of one.
TEST(DifferentialScale, SppmFootprintsShrinkAsOneOverTheRootOfTheIterations) {
  // The pixels' green values.
  auto render = [](int iterations) {
    test::TestRenderOptions o;
    o.build.seed = 3;
    std::vector<double> green;
    for (const Spectrum& v :
         test::pixelValues(test::renderSceneText(checkSquaresUnderSppm(iterations), o).film()))
      green.push_back(v[1]);
    return green;
  };
  // One iteration: the full pixel, c = 0.5 and c^2 = 0.25 in every pixel.
  for (double v : render(1)) EXPECT_NEAR(v, 0.25, 1e-5);
  // 64 iterations at scale 1/8 (0.25 in every pixel with a whole pixel's footprint): 4,096
  // visible points of c^2 in [0, 1] (standard deviation at most 0.5, so the mean's at most
  // 0.008); 0.03 is more than 3.8 of them.
  std::vector<double> green = render(64);
  double mean64 = std::accumulate(green.begin(), green.end(), 0.0) / double(green.size());
  auto [lo, hi] = std::minmax_element(green.begin(), green.end());
  std::printf("64 iterations: mean %.4f, pixels %.4f to %.4f\n", mean64, *lo, *hi);
  EXPECT_NEAR(mean64, 0.3906, 0.03);
}
