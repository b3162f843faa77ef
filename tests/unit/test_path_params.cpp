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
  EXPECT_EQ(v3.lightStrategy, LightSampleStrategy::SpatialUnlessMany);
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

// pbrt-v3's default is "spatial" up to kSpatialMostLights lights and the light tree beyond, with a
// warning at the integrator statement that says so; a strategy given by name is kept.
TEST(PathParams, ManyLightsTakeTheTreeByDefault) {
  const auto v3 = LightSampleStrategy::SpatialUnlessMany;
  EXPECT_EQ(resolvedLightStrategy(v3, kSpatialMostLights), LightSampleStrategy::Spatial);
  EXPECT_EQ(resolvedLightStrategy(v3, kSpatialMostLights + 1), LightSampleStrategy::Bvh);
  EXPECT_EQ(resolvedLightStrategy(LightSampleStrategy::Spatial, 100000),
            LightSampleStrategy::Spatial);
  EXPECT_EQ(lightStrategyNotice(v3, kSpatialMostLights), "");
  EXPECT_EQ(lightStrategyNotice(LightSampleStrategy::Spatial, 100000), "");
  // A pbrt-v3 scene of kSpatialMostLights + 1 emitting triangles (a strip of them) and one of as
  // many naming "spatial".
  auto scene = [](const std::string& integrator) {
    const int n = int(kSpatialMostLights) + 1;
    std::string s =
        "Camera \"perspective\"\nFilm \"image\" \"integer xresolution\" [4] "
        "\"integer yresolution\" [4]\n" +
        integrator +
        "\nWorldBegin\nAreaLightSource \"diffuse\"\nShape \"trianglemesh\" "
        "\"integer indices\" [";
    for (int i = 0; i < n; ++i)
      s.append(std::to_string(i))
          .append(" ")
          .append(std::to_string(i + 1))
          .append(" ")
          .append(std::to_string(i + 2))
          .append(" ");
    s += "] \"point P\" [";
    for (int i = 0; i < n + 2; ++i)
      s.append(std::to_string(i * 0.01)).append(i % 2 ? " 1 5 " : " 0 5 ");
    s += "]\nWorldEnd\n";
    return s;
  };
  for (const char* integrator : {"path", "volpath"}) {
    std::vector<std::string> warnings;
    BuildOptions o;
    o.warn = [&](const FileLoc& loc, const std::string& message) {
      warnings.push_back(std::to_string(loc.line) + ": " + message);
    };
    std::string statement = std::string("Integrator \"") + integrator + "\"";
    test::buildSceneText(scene(statement), o);
    bool told = false;
    for (const std::string& w : warnings)
      told |=
          w.rfind("3: the scene has 4097 lights", 0) == 0 && w.find("\"bvh\"") != std::string::npos;
    EXPECT_TRUE(told) << integrator;
    warnings.clear();
    test::buildSceneText(scene(statement + " \"string lightsamplestrategy\" \"spatial\""), o);
    for (const std::string& w : warnings) EXPECT_EQ(w.find("lights, more than"), std::string::npos);
  }
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
