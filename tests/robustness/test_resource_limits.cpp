// Scenes that would exhaust memory or a thread's stack are refused up front with a SceneError at
// the statement, instead of ending in std::bad_alloc or a segmentation fault: deeply nested
// textures and films too large to hold. (Subdivision levels: test_loop_subdiv_shape.cpp; maxdepth
// of the recursive integrators: test_whitted_ao.cpp.)
#include <gtest/gtest.h>

#include "support/render_scene.h"

namespace candela {
namespace {

// A chain of `depth` textures, each scaling the one before, used by the sphere's material.
std::string textureChain(int depth) {
  std::string s =
      "Film \"image\" \"integer xresolution\" [4] \"integer yresolution\" [4]\n"
      "WorldBegin\n"
      "Texture \"t0\" \"float\" \"constant\" \"float value\" [0.5]\n";
  for (int i = 1; i < depth; ++i)
    s.append("Texture \"t")
        .append(std::to_string(i))
        .append("\" \"float\" \"scale\" \"texture tex1\" \"t")
        .append(std::to_string(i - 1))
        .append("\" \"float tex2\" [1]\n");
  return s.append("Material \"matte\" \"texture sigma\" \"t")
      .append(std::to_string(depth - 1))
      .append("\"\nShape \"sphere\"\nWorldEnd\n");
}

TEST(ResourceLimits, TexturesNestedBeyond500AreASceneError) {
  EXPECT_NO_THROW(test::buildSceneText(textureChain(500)));
  try {
    test::buildSceneText(textureChain(20000));
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("is nested more than 500 textures deep"),
              std::string::npos)
        << e.what();
  }
}

TEST(ResourceLimits, FilmsBeyond2To27PixelsAreASceneErrorUnlessCropped) {
  const char* huge =
      "Film \"image\" \"integer xresolution\" [100000] \"integer yresolution\" [100000]\n"
      "WorldBegin\nWorldEnd\n";
  try {
    test::buildSceneText(huge);
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.location().line, 1);
    EXPECT_NE(std::string(e.what()).find("film: 10000000000 pixels to render"), std::string::npos)
        << e.what();
  }
  // A crop window of it is fine: only the pixels rendered are kept.
  BuildOptions crop;
  crop.cropWindow = Bounds2f(Point2f(0, 0), Point2f(0.001f, 0.001f));
  // (100 or 101 pixels a side: ceil(100000 x 0.001f) depends on 0.001f's rounding.)
  int area = test::buildSceneText(huge, crop).film().pixelBounds().area();
  EXPECT_GE(area, 100 * 100);
  EXPECT_LE(area, 101 * 101);
}

}  // namespace
}  // namespace candela
