// "sppm"'s scene parameters (pbrt-v3's): every bad value is a SceneError located at the
// parameter; good ones build, unknown names are reported and imagewritefrequency is accepted.
#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "integrators/sppm/sppm_integrator.h"
#include "support/parameter_errors.h"
#include "support/render_scene.h"

namespace candela {
namespace {

std::string sceneWith(const std::string& parameter) {
  return test::parameterScene("Integrator \"sppm\"", parameter);
}

TEST(SppmParameters, EveryBadValueIsALocatedSceneError) {
  test::expectParameterErrorsLocated(
      "Integrator \"sppm\"",
      {"\"integer numiterations\" [0]", "\"integer numiterations\" [-2]", "\"float radius\" [0]",
       "\"float radius\" [-1]", "\"integer maxdepth\" [-1]", "\"integer photonsperiteration\" [0]",
       "\"integer photonsperiteration\" [-2]"});
}

const SppmIntegrator& sppmOf(test::RenderedScene& built) {
  auto* r = dynamic_cast<const SppmIntegrator*>(built.job().integrator.get());
  if (!r) throw std::runtime_error("not an SPPM renderer");
  return *r;
}

TEST(SppmParameters, DefaultsGoodValuesAndUnknownNames) {
  auto defaults = test::buildSceneText(sceneWith(""));
  const SppmSettings& d = sppmOf(defaults).settings();
  EXPECT_EQ(d.iterations, 64);
  EXPECT_EQ(d.maxDepth, 5);
  EXPECT_EQ(d.photonsPerIteration, -1);
  EXPECT_EQ(d.initialRadius, 1);

  BuildOptions options;
  std::string warnings;
  options.warn = [&](const FileLoc&, const std::string& m) { warnings += m + "\n"; };
  auto good = test::buildSceneText(
      sceneWith("\"integer numiterations\" [3] \"integer maxdepth\" [0] "
                "\"integer photonsperiteration\" [100] \"float radius\" [0.01] "
                "\"integer imagewritefrequency\" [1]"),
      options);
  EXPECT_EQ(warnings, "");
  const SppmSettings& s = sppmOf(good).settings();
  EXPECT_EQ(s.iterations, 3);
  EXPECT_EQ(s.maxDepth, 0);
  EXPECT_EQ(s.photonsPerIteration, 100);
  EXPECT_FLOAT_EQ(s.initialRadius, 0.01f);

  test::buildSceneText(sceneWith("\"integer numiteration\" [8]"), options);
  EXPECT_NE(warnings.find("numiteration"), std::string::npos) << warnings;

  // --quick renders a sixteenth of the iterations (pbrt-v3's rule).
  BuildOptions quick;
  quick.quick = true;
  auto q = test::buildSceneText(sceneWith(""), quick);
  EXPECT_EQ(sppmOf(q).settings().iterations, 4);
}

}  // namespace
}  // namespace candela
