// A "nurbs" shape through the whole path (parser, shape factory, Embree, shading with its uv): a
// bilinear NURBS patch is the same textured quad as the equivalent "trianglemesh", so the two
// renders agree up to rounding (test_aggregate_renders.cpp's criterion).
#include <gtest/gtest.h>

#include "support/image_compare.h"
#include "support/render_scene.h"

namespace candela {
namespace {

ImageBuffer render(const std::string& shape) {
  std::string scene = R"(
LookAt 0.4 -1.5 2  0.5 0.5 0  0 0 1
Camera "perspective" "float fov" [28]
Film "image" "integer xresolution" [48] "integer yresolution" [48]
Sampler "stratified" "integer xsamples" [2] "integer ysamples" [2]
PixelFilter "box"
WorldBegin
LightSource "point" "point from" [0.5 -1 3] "rgb I" [10 10 10]
Texture "checks" "spectrum" "checkerboard" "float uscale" [6] "float vscale" [6]
  "rgb tex1" [0.9 0.2 0.1] "rgb tex2" [0.1 0.3 0.9]
Material "matte" "texture Kd" "checks"
)" + shape + "WorldEnd\n";
  test::TestRenderOptions o;
  o.build.seed = 3;
  return test::renderSceneText(scene, o).film().image();
}

TEST(NurbsScene, BilinearPatchRendersAsTheQuad) {
  ImageBuffer nurbs = render(R"(Shape "nurbs" "integer nu" [2] "integer uorder" [2]
  "float uknots" [0 0 1 1] "integer nv" [2] "integer vorder" [2] "float vknots" [0 0 1 1]
  "point P" [0 0 0  1 0 0  0 1 0  1 1 0]
)");
  ImageBuffer quad = render(R"(Shape "trianglemesh" "integer indices" [0 1 3  0 3 2]
  "point P" [0 0 0  1 0 0  0 1 0  1 1 0] "float uv" [0 0  1 0  0 1  1 1]
)");
  test::RoundingComparison c = test::compareUpToRounding(nurbs, quad, 1e-4f, 1e-5f);
  std::printf("%zu of %zu pixels beyond rounding, %zu of %zu values identical\n", c.flipped,
              c.pixels, c.identicalValues, c.values);
  size_t lit = 0;
  for (size_t px = 0; px < quad.pixelCount(); ++px) lit += quad.data[px * quad.channelCount()] > 0;
  EXPECT_GT(lit, quad.pixelCount() / 4);
  // The diced mesh splits cells along other diagonals than the quad: only edge-grazing rays may
  // differ.
  EXPECT_LE(double(c.flipped), 0.01 * double(c.pixels));
  EXPECT_NEAR(c.sumA, c.sumB, 1e-3 * c.sumB);
}

TEST(NurbsScene, BadKnotsAreASceneErrorAtTheParameter) {
  try {
    render(R"(Shape "nurbs" "integer nu" [2] "integer uorder" [2]
  "float uknots" [0 1 0.5 1] "integer nv" [2] "integer vorder" [2] "float vknots" [0 0 1 1]
  "point P" [0 0 0  1 0 0  0 1 0  1 1 0]
)");
    FAIL() << "no error";
  } catch (const SceneError& e) {
    std::string m = e.what();
    EXPECT_NE(m.find("test.pbrt:13:"), std::string::npos) << m;
    EXPECT_NE(m.find("nurbs: \"uknots\" must be nondecreasing"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace candela
