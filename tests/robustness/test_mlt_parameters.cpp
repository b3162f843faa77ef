// The Metropolis renderers' scene parameters: every bad value is a SceneError located at the
// parameter, unknown parameters are reported, and the defaults build.
#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "integrators/metropolis/metropolis_integrator.h"
#include "support/parameter_errors.h"
#include "support/render_scene.h"

namespace candela {
namespace {

std::string sceneWith(const std::string& statement, const std::string& parameter) {
  return test::parameterScene(statement, parameter);
}

TEST(MltParameters, EveryBadValueIsALocatedSceneError) {
  test::expectParameterErrorsLocated(
      "Integrator \"mlt\"",
      {"\"integer maxdepth\" [-1]", "\"integer bootstrapsamples\" [0]",
       "\"integer bootstrapsamples\" [-5]", "\"integer chains\" [0]", "\"integer chains\" [-2]",
       "\"integer mutationsperpixel\" [-1]", "\"integer mutationsperpixel\" [0]",
       "\"float largestepprobability\" [-0.1]", "\"float largestepprobability\" [1.5]",
       "\"float sigma\" [0]", "\"float sigma\" [-0.01]"});
}

TEST(MetropolisParameters, EveryBadValueIsALocatedSceneError) {
  test::expectParameterErrorsLocated(
      "Renderer \"metropolis\"",
      {"\"integer maxdepth\" [-1]", "\"integer bootstrapsamples\" [0]",
       "\"integer samplesperpixel\" [-3]", "\"integer directsamples\" [0]",
       "\"integer maxconsecutiverejects\" [-1]", "\"float largestepprobability\" [2]",
       "\"float largestepprobability\" [-1]"});
}

TEST(MltParameters, GoodValuesBuildAndUnknownNamesAreReported) {
  EXPECT_NO_THROW(test::buildSceneText(
      sceneWith("Integrator \"mlt\"",
                "\"integer maxdepth\" [0] \"integer bootstrapsamples\" [1] \"integer chains\" [1] "
                "\"integer mutationsperpixel\" [1] \"float largestepprobability\" [1] "
                "\"float sigma\" [0.5]")));
  EXPECT_NO_THROW(test::buildSceneText(
      sceneWith("Renderer \"metropolis\"",
                "\"float largestepprobability\" [0] \"bool bidirectional\" \"false\" "
                "\"bool dodirectseparately\" \"false\" \"integer directsamples\" [1]")));
  for (const char* statement : {"Integrator \"mlt\"", "Renderer \"metropolis\""}) {
    BuildOptions options;
    std::string warnings;
    options.warn = [&](const FileLoc&, const std::string& m) { warnings += m + "\n"; };
    test::buildSceneText(sceneWith(statement, "\"integer mutations\" [8]"), options);
    EXPECT_NE(warnings.find("mutations"), std::string::npos) << warnings;
  }
}

// pbrt-v2's Renderer "metropolis" no longer falls back to the sampler renderer with a warning.
TEST(MetropolisParameters, RendererIsAvailable) {
  BuildOptions options;
  std::string warnings;
  options.warn = [&](const FileLoc&, const std::string& m) { warnings += m + "\n"; };
  test::RenderedScene r = test::buildSceneText(sceneWith("Renderer \"metropolis\"", ""), options);
  EXPECT_TRUE(dynamic_cast<const MetropolisIntegrator*>(r.job().integrator.get()) != nullptr);
  EXPECT_EQ(warnings.find("not available"), std::string::npos) << warnings;
}

// A camera without importance cannot take splats from light paths: a SceneError naming it.
TEST(MltParameters, CameraWithoutImportanceIsASceneError) {
  std::string text =
      "Camera \"environment\"\n" + sceneWith("Integrator \"mlt\"", "\"integer chains\" [2]");
  EXPECT_THROW(test::buildSceneText(text), SceneError);
}

}  // namespace
}  // namespace candela
