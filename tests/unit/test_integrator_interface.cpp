// Every integrator behind the one Integrator interface: what it says of its pixels decides what
// the command may do (split by sample range, estimate error from variance), so each answer is held
// to how the integrator really renders; and a pixel-sample integrator's render() in passes gives
// the bits of its renderSamples() in one.
#include <gtest/gtest.h>

#include <string>

#include "integrators/integrator_plugins.h"
#include "integrators/pixel_sample_integrator.h"
#include "support/render_scene.h"

namespace candela {
namespace {

// The statement of the dialect the integrator belongs to: pbrt-v3's Integrator, else pbrt-v2's
// SurfaceIntegrator.
std::string integratorStatement(const std::string& name, bool pbrtV3 = true) {
  if (name == "sppm") return "Integrator \"sppm\" \"integer numiterations\" [2]";
  if (name == "mlt") return "Integrator \"mlt\" \"integer mutationsperpixel\" [2]";
  std::string statement = pbrtV3 ? "Integrator \"" : "SurfaceIntegrator \"";
  return statement.append(name).append("\"");
}

test::RenderedScene built(const std::string& statement) {
  BuildOptions options;
  options.sppOverride = 2;
  options.warn = [](const FileLoc&, const std::string&) {};
  return test::buildSceneText(test::cornellBoxText(8, statement), options);
}

PixelLight expectedPixelLight(const std::string& name) {
  if (name == "bdpt" || name == "bidirectional") return PixelLight::Splatted;
  if (name == "sppm" || name == "mlt") return PixelLight::WholeImage;
  return PixelLight::OwnSamples;
}

TEST(IntegratorInterface, EachIntegratorSaysWhatItsPixelsAreMadeOf) {
  int checked = 0;
  for (const IntegratorPlugin& plugin : integratorPlugins()) {
    const std::string name(plugin.spec.name);
    test::RenderedScene r = built(integratorStatement(name, plugin.spec.dialects & kPbrtV3));
    const Integrator& integrator = *r.job().integrator;
    EXPECT_EQ(integrator.pixelLight(), expectedPixelLight(name)) << name;
    // Whole-image integrators are exactly those that are no pixel-sample integrator.
    const bool pixelSamples = dynamic_cast<const PixelSampleIntegrator*>(&integrator) != nullptr;
    EXPECT_EQ(pixelSamples, plugin.makePixelSampleIntegrator != nullptr) << name;
    EXPECT_EQ(!pixelSamples, integrator.pixelLight() == PixelLight::WholeImage) << name;
    ++checked;
  }
  EXPECT_GE(checked, 12);
}

// pbrt-v2's Renderer "metropolis" is an integrator of the whole image as well.
TEST(IntegratorInterface, TheMetropolisRendererRendersTheWholeImage) {
  test::RenderedScene r =
      built("SurfaceIntegrator \"path\"\nRenderer \"metropolis\" \"integer samplesperpixel\" [2]");
  EXPECT_EQ(r.job().integrator->pixelLight(), PixelLight::WholeImage);
}

// A splatting integrator's light really lands outside its samples' pixels: with a crop window
// of one pixel, light paths from the whole image's samples still reach it, so the pixel-sample
// count is the full image's.
TEST(IntegratorInterface, ASplattingIntegratorTakesEveryPixelsSamplesUnderACrop) {
  for (const std::string name : {"bdpt", "path"}) {
    BuildOptions options;
    options.sppOverride = 2;
    options.cropWindow = Bounds2f(Point2f(0.5f, 0.5f), Point2f(0.625f, 0.625f));
    test::RenderedScene r =
        test::buildSceneText(test::cornellBoxText(8, integratorStatement(name)), options);
    ProgressiveOptions po;
    po.render.quiet = true;
    ProgressiveResult result = renderJob(r.job(), po);
    const uint64_t pixels = name == "bdpt" ? 64 : 1;
    EXPECT_EQ(result.total.samples, pixels * 2) << name;
  }
}

// render() in doubling passes adds the same samples in the same order as one renderSamples().
TEST(IntegratorInterface, PassesGiveTheBitsOfOneRenderOfTheSameSamples) {
  for (const std::string name : {"path", "bdpt", "irradiancecache"}) {
    const bool v3 = name != "irradiancecache";
    test::RenderedScene once = built(integratorStatement(name, v3));
    test::PixelPasses(once.job())
        .render(*once.job().scene, *once.job().film, RenderOptions{1, 4, true});
    test::RenderedScene passes = built(integratorStatement(name, v3));
    ProgressiveOptions po;
    po.render = RenderOptions{2, 3, true};
    po.afterPass = [](const PassReport&) { return true; };
    ProgressiveResult result = renderJob(passes.job(), po);
    EXPECT_EQ(result.passes, 2) << name;  // 1 then 2 samples per pixel
    EXPECT_EQ(test::pixelValues(*once.job().film), test::pixelValues(*passes.job().film)) << name;
  }
}

}  // namespace
}  // namespace candela
