// Rendering in ACEScg: input colours are converted once at load, so for a scene whose light
// transport is linear in each colour (coloured surfaces under white light, one bounce) the ACEScg
// render equals OCIO's conversion of the Rec.709 render.
#include <gtest/gtest.h>

#include "film/output/image_output.h"
#include "support/render_scene.h"

namespace candela {
namespace {

const char* kScene =
    "LookAt 0 0 -5  0 0 0  0 1 0\n"
    "Camera \"perspective\" \"float fov\" [40]\n"
    "Film \"image\" \"integer xresolution\" [24] \"integer yresolution\" [24]\n"
    "Sampler \"stratified\" \"integer xsamples\" [2] \"integer ysamples\" [2]\n"
    "SurfaceIntegrator \"directlighting\"\n"
    "WorldBegin\n"
    "LightSource \"point\" \"point from\" [0 2 -5] \"rgb I\" [20 20 20]\n"
    "AttributeBegin\n"
    "  AreaLightSource \"diffuse\" \"rgb L\" [0.3 0.3 0.3]\n"
    "  Translate 0 0 6\n  Shape \"sphere\" \"float radius\" [0.5]\n"
    "AttributeEnd\n"
    "Material \"matte\" \"rgb Kd\" [0.8 0.1 0.05]\n"
    "AttributeBegin\n Translate -1 0 0\n Shape \"sphere\" \"float radius\" [0.8]\nAttributeEnd\n"
    "Material \"matte\" \"rgb Kd\" [0.05 0.3 0.9]\n"
    "AttributeBegin\n Translate 1 0 0\n Shape \"sphere\" \"float radius\" [0.8]\nAttributeEnd\n"
    "WorldEnd\n";

TEST(WorkingColorSpace, AcesCgRenderEqualsConvertedRec709Render) {
  ColorManagement cm;
  const std::string linear = cm.sceneLinearName(), aces = cm.canonicalName("acescg");
  ImageBuffer basis(3, 1, {"R", "G", "B"});
  for (int i = 0; i < 3; ++i) basis.at(i, 0, i) = 1;
  cm.convert(basis, linear, aces);
  std::array<Float, 9> m;
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col) m[3 * row + col] = basis.at(col, 0, row);
  // The documented Rec.709 -> ACEScg matrix's first row.
  EXPECT_NEAR(m[0], 0.6131, 1e-3);
  EXPECT_NEAR(m[1], 0.3395, 1e-3);

  ImageBuffer rec709 = test::renderSceneText(kScene).film().image();
  test::TestRenderOptions o;
  o.build.colorMatrix = m;
  ImageBuffer acescg = test::renderSceneText(kScene, o).film().image();
  cm.convert(rec709, linear, aces);
  ASSERT_EQ(rec709.data.size(), acescg.data.size());
  double worst = 0, maxValue = 0;
  for (size_t i = 0; i < acescg.data.size(); ++i) {
    worst = std::max(worst, double(std::abs(rec709.data[i] - acescg.data[i])));
    maxValue = std::max(maxValue, double(acescg.data[i]));
  }
  EXPECT_GT(maxValue, 0.1);
  EXPECT_LT(worst, 1e-5);
}

}  // namespace
}  // namespace candela
