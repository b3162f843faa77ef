// scenes/materials: every material on a sphere, rendered small and compared with a stored
// reference (tests/data/materials-reference.exr: the same 120x60 view at 1024 spp with another
// seed, made by candela and checked by eye). A wrong BSDF changes the image by far more than the
// noise of a few samples per pixel; the threshold is set from that noise, below.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "film/error_metrics.h"
#include "film/output/image_output.h"
#include "support/render_scene.h"

namespace candela {
namespace {

std::string smallMaterialsScene() {
  std::ifstream in(std::string(CANDELA_SOURCE_DIR) + "/scenes/materials/materials.pbrt");
  std::stringstream ss;
  ss << in.rdbuf();
  std::string s = ss.str();
  const std::string res = "\"integer xresolution\" [480] \"integer yresolution\" [240]";
  size_t at = s.find(res);
  EXPECT_NE(at, std::string::npos);
  if (at != std::string::npos)
    s.replace(at, res.size(), "\"integer xresolution\" [120] \"integer yresolution\" [60]");
  return s;
}

TEST(MaterialsScene, RendersFiniteAndMatchesTheReference) {
  test::TestRenderOptions o;
  o.build.sppOverride = 32;
  o.build.seed = 1;
  auto r = test::renderSceneText(smallMaterialsScene(), o);
  EXPECT_EQ(r.results.front().nonFiniteSamples, 0u);
  ImageBuffer img = r.film().image();
  for (float v : img.data) ASSERT_TRUE(std::isfinite(v));

  ImageBuffer reference =
      readImage(std::string(CANDELA_TEST_DATA_DIR) + "/materials-reference.exr");
  ErrorMetrics m = compareToReference(r.film(), reference);
  // The expected relMSE of an unbiased 32-spp render is what its own variance predicts (the
  // reference adds 1/32 of that); allow twice that plus the interval's half-width for the
  // heavy-tailed noise of caustics through the glass sphere. A material that is wrong by 10% in
  // reflectance over a sphere adds ~1e-2 relMSE over its ~3% of the pixels: several times more.
  double allowed = 2 * m.relmseFromVariance * (1 + 1.0 / 32) + m.relmseCi95;
  std::printf("relMSE %.5f, predicted from variance %.5f, allowed %.5f\n", m.relmse,
              m.relmseFromVariance, allowed);
  EXPECT_LT(m.relmse, allowed);
}

}  // namespace
}  // namespace candela
