// Integrator "path": pbrt-v3's "rrthreshold" and "lightsamplestrategy", their defaults by the
// scene's dialect, located errors for bad values, and the threshold's effect on which paths face
// Russian roulette.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "assembly/plugin_factories.h"
#include "integrators/path.h"
#include "support/param_items.h"
#include "support/render_scene.h"

namespace candela {
namespace {

const FileLoc kStatement{"s.pbrt", 3, 1};
const FileLoc kParam{"s.pbrt", 7, 5};

PathSettings settingsOf(std::vector<ParamItem> items, SceneDialect dialect) {
  PluginDesc d{"path", {}, kStatement};
  for (ParamItem& item : items) d.params.add(std::move(item));
  auto integrator = createSurfaceIntegrator(d, nullptr, {}, dialect);
  auto* path = dynamic_cast<PathIntegrator*>(integrator.get());
  EXPECT_NE(path, nullptr);
  return path ? path->settings() : PathSettings{};
}

TEST(PathParams, DefaultsFollowTheDialect) {
  PathSettings v2 = settingsOf({}, SceneDialect::PbrtV2);
  EXPECT_EQ(v2.lightStrategy, LightSampleStrategy::Uniform);
  EXPECT_FALSE(v2.pbrtV3Roulette);
  EXPECT_EQ(v2.maxDepth, 5);
  PathSettings v3 = settingsOf({}, SceneDialect::PbrtV3);
  EXPECT_EQ(v3.lightStrategy, LightSampleStrategy::Spatial);
  EXPECT_TRUE(v3.pbrtV3Roulette);
  EXPECT_EQ(v3.rrThreshold, 1);
  // Given in a pbrt-v2 scene, the parameters take effect there too.
  PathSettings given = settingsOf(
      {test::floats("rrthreshold", {0.25f}), test::strings("lightsamplestrategy", {"power"})},
      SceneDialect::PbrtV2);
  EXPECT_TRUE(given.pbrtV3Roulette);
  EXPECT_EQ(given.rrThreshold, 0.25f);
  EXPECT_EQ(given.lightStrategy, LightSampleStrategy::Power);
}

void expectLocatedError(std::vector<ParamItem> items, const std::string& mentions) {
  try {
    settingsOf(std::move(items), SceneDialect::PbrtV3);
    ADD_FAILURE() << "no error for " << mentions;
  } catch (const SceneError& e) {
    EXPECT_EQ(e.location().line, kParam.line) << e.what();
    EXPECT_NE(std::string(e.what()).find(mentions), std::string::npos) << e.what();
  }
}

TEST(PathParams, BadValuesAreLocatedSceneErrors) {
  expectLocatedError(
      {test::strings("lightsamplestrategy", {"tree"}, kParam)},
      "\"lightsamplestrategy\" must be one of uniform, power, spatial, bvh (got \"tree\")");
  for (Float bad : {-1.f, std::numeric_limits<Float>::infinity(), std::nanf("")})
    expectLocatedError({test::floats("rrthreshold", {bad}, kParam)}, "rrthreshold");
}

// A closed diffuse box (albedo 0.5): no path escapes and every BSDF sample continues, so without
// roulette every path traces maxdepth + 1 closest-hit rays.
uint64_t closestHitRays(const std::string& integratorParams) {
  std::string text =
      "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"perspective\" \"float fov\" [60]\n"
      "Film \"image\" \"integer xresolution\" [8] \"integer yresolution\" [8]\n"
      "Sampler \"random\" \"integer pixelsamples\" [4]\n"
      "Integrator \"path\" \"integer maxdepth\" [6] " +
      integratorParams +
      "\nWorldBegin\n"
      "AttributeBegin\n  AreaLightSource \"diffuse\" \"rgb L\" [1 1 1]\n"
      "  Translate 0 0.9 0\n  Rotate 90 1 0 0\n  Shape \"disk\" \"float radius\" [0.2]\n"
      "AttributeEnd\n"
      "Material \"matte\" \"rgb Kd\" [0.5 0.5 0.5]\n"
      "ReverseOrientation\nShape \"sphere\" \"float radius\" [1]\n"
      "WorldEnd\n";
  test::TestRenderOptions o;
  o.render.nThreads = 1;
  return test::renderSceneText(text, o).results.front().rays.intersectionRays;
}

TEST(PathParams, RouletteOnlyBelowTheThreshold) {
  const uint64_t paths = 8 * 8 * 4;
  // Throughputs stay below 1 (albedo 0.5): none reaches a threshold of 0, every one is below 1.
  EXPECT_EQ(closestHitRays("\"float rrthreshold\" [0]"), paths * 7);
  uint64_t withRoulette = closestHitRays("");
  EXPECT_LT(withRoulette, paths * 7);
  EXPECT_GT(withRoulette, paths * 4);  // no roulette before the fourth bounce
}

}  // namespace
}  // namespace candela
