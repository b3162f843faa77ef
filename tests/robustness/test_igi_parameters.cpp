// "igi"'s scene parameters: every bad value is a SceneError located at the parameter, and
// --quick traces a quarter of the light paths.
#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "integrators/instant_global_illumination.h"
#include "support/parameter_errors.h"
#include "support/render_scene.h"

namespace candela {
namespace {

std::string sceneWith(const std::string& parameter) {
  return test::parameterScene("SurfaceIntegrator \"igi\"", parameter);
}

TEST(IgiParameters, EveryBadValueIsALocatedSceneError) {
  test::expectParameterErrorsLocated(
      "SurfaceIntegrator \"igi\"",
      {"\"integer nlights\" [0]", "\"integer nlights\" [-3]", "\"integer nsets\" [0]",
       "\"float glimit\" [0]", "\"float glimit\" [-1]", "\"integer gathersamples\" [-1]",
       "\"float rrthreshold\" [-0.5]", "\"integer maxdepth\" [-1]"});
}

TEST(IgiParameters, GoodValuesBuildAndUnknownNamesAreReported) {
  EXPECT_NO_THROW(test::buildSceneText(sceneWith(
      "\"integer nlights\" [1] \"integer nsets\" [1] \"float glimit\" [1e-3] "
      "\"integer gathersamples\" [0] \"float rrthreshold\" [0] \"integer maxdepth\" [0]")));
  BuildOptions options;
  std::string warnings;
  options.warn = [&](const FileLoc&, const std::string& m) { warnings += m + "\n"; };
  test::buildSceneText(sceneWith("\"integer nlight\" [8]"), options);
  EXPECT_NE(warnings.find("nlight"), std::string::npos) << warnings;
}

// The number of paths the VPL sets were traced from, as the integrator holds it.
int pathsPerSet(const std::string& parameter, bool quick) {
  BuildOptions options;
  options.quick = quick;
  auto built = test::buildSceneText(sceneWith(parameter), options);
  auto* igi =
      dynamic_cast<const InstantGlobalIlluminationIntegrator*>(built.job().integrator.get());
  EXPECT_NE(igi, nullptr);
  return igi ? igi->virtualLights().pathsPerSet : -1;
}

TEST(IgiParameters, QuickTracesAQuarterOfTheLightPaths) {
  EXPECT_EQ(pathsPerSet("", false), 64);
  EXPECT_EQ(pathsPerSet("", true), 16);
  EXPECT_EQ(pathsPerSet("\"integer nlights\" [100]", true), 25);
  EXPECT_EQ(pathsPerSet("\"integer nlights\" [3]", true), 1);
  // A bad count stays an error at its own place under --quick too.
  try {
    pathsPerSet("\"integer nlights\" [0]", true);
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.location().line, 3) << e.what();
  }
}

TEST(IgiParameters, StatsCountTheVirtualLights) {
  // A point light inside a closed sphere: every light path hits the sphere, so each of the
  // 4 x 8 paths leaves at least one VPL.
  auto built = test::buildSceneText(
      "SurfaceIntegrator \"igi\" \"integer nlights\" [8]\n"
      "WorldBegin\n"
      "LightSource \"point\"\n"
      "Material \"matte\" \"rgb Kd\" [0.5 0.5 0.5]\n"
      "Shape \"sphere\" \"float radius\" [1]\n"
      "WorldEnd\n");
  const auto& igi =
      dynamic_cast<const InstantGlobalIlluminationIntegrator&>(*built.job().integrator);
  long count = long(igi.virtualLights().count()), bytes = long(igi.virtualLights().memoryBytes());
  EXPECT_GE(count, 32);
  EXPECT_GE(bytes, count * long(sizeof(VirtualPointLight)));
  std::string report = igi.statsReport();
  EXPECT_NE(report.find("virtual point lights  " + std::to_string(count)), std::string::npos)
      << report;
}

}  // namespace
}  // namespace candela
