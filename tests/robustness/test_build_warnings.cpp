// Every warning of a scene build reaches BuildOptions::warn with its file:line:col (the command
// line prints them, or, with -q, drops them): none goes to standard error on its own.
#include <gtest/gtest.h>

#include "support/render_scene.h"

namespace candela {
namespace {

TEST(BuildWarnings, SamplerAndUnusedParametersReachTheSink) {
  const char* scene = R"(Film "image" "integer xresolution" [8] "integer yresolution" [8]
Sampler "lowdiscrepancy" "integer pixelsamples" [6]
WorldBegin
Shape "sphere" "float radius" [1] "float nonesuch" [2]
WorldEnd
)";
  std::vector<std::string> warnings;
  BuildOptions options;
  options.warn = [&](const FileLoc& loc, const std::string& message) {
    warnings.push_back(loc.str() + ": " + message);
  };
  testing::internal::CaptureStderr();
  test::buildSceneText(scene, options);
  std::string stderrText = testing::internal::GetCapturedStderr();
  EXPECT_EQ(stderrText, "");
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].find("test.pbrt:2:"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("rounded up to the power of two 8"), std::string::npos);
  EXPECT_NE(warnings[1].find("test.pbrt:4:"), std::string::npos) << warnings[1];
  EXPECT_NE(warnings[1].find("nonesuch"), std::string::npos) << warnings[1];

  // No sink (quiet): nothing at all, not even on standard error.
  testing::internal::CaptureStderr();
  test::buildSceneText(scene, BuildOptions{});
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
  // --quick takes an eighth of the rounded count: 1, which needs no rounding, so only the unused
  // parameter is reported.
  warnings.clear();
  options.quick = true;
  test::RenderedScene quick = test::buildSceneText(scene, options);
  EXPECT_EQ(quick.job().sampler->samplesPerPixel(), 1);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("nonesuch"), std::string::npos) << warnings[0];
  // --spp replaces the scene's pixelsamples, which is still read (and checked), so it is not
  // reported unused.
  warnings.clear();
  options.quick = false;
  options.sppOverride = 16;
  EXPECT_EQ(test::buildSceneText(scene, options).job().sampler->samplesPerPixel(), 16);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("nonesuch"), std::string::npos) << warnings[0];
  // A count from --spp that needs rounding is blamed on --spp, not on the scene.
  warnings.clear();
  options.sppOverride = 6;
  EXPECT_EQ(test::buildSceneText(scene, options).job().sampler->samplesPerPixel(), 8);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings[0], "--spp: lowdiscrepancy sampler: --spp 6 rounded up to the power of two 8");
}

TEST(BuildWarnings, FilmParametersAreCheckedLikeEveryStatement) {
  // pbrt-v3's film parameters are read; a misspelt one is reported at its location (before, no
  // Film parameter was ever reported). --quick's own resolution does not count as unused.
  const char* scene = R"(Film "image" "integer xresolution" [8] "integer yresolution" [8]
  "float scale" [1.5] "float maxsampleluminance" [10] "float diagonal" [35]
  "integer xresolutoin" [16]
WorldBegin
WorldEnd
)";
  for (bool quick : {false, true}) {
    std::vector<std::string> warnings;
    BuildOptions options;
    options.quick = quick;
    options.warn = [&](const FileLoc& loc, const std::string& message) {
      warnings.push_back(loc.str() + ": " + message);
    };
    test::RenderedScene r = test::buildSceneText(scene, options);
    EXPECT_EQ(r.film().scale(), 1.5f);
    ASSERT_EQ(warnings.size(), 1u) << quick;
    EXPECT_NE(warnings[0].find("test.pbrt:3:"), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find("xresolutoin"), std::string::npos) << warnings[0];
  }
}

}  // namespace
}  // namespace candela
