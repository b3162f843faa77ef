// pbrt's conventions decide where things land in the image: a left-handed world, LookAt's up
// vector up on screen, +x world to the right for a camera looking down +z, and the fov spanning
// the shorter image axis. A scene file written for pbrt must frame the same picture here.
#include <gtest/gtest.h>

#include <string>

#include "support/render_scene.h"

namespace candela {
namespace {

// Sum of red over a rectangle of pixels [x0, x1) x [y0, y1).
double energy(const Film& film, int x0, int x1, int y0, int y1) {
  double s = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) s += film.pixelValue(Point2i(x, y))[0];
  return s;
}

std::string sceneWithSphereAt(const std::string& translate, int xres, int yres,
                              const std::string& fov = "60") {
  return "LookAt 0 0 -10  0 0 0  0 1 0\n"
         "Camera \"perspective\" \"float fov\" [" +
         fov +
         "]\n"
         "Film \"image\" \"integer xresolution\" [" +
         std::to_string(xres) + "] \"integer yresolution\" [" + std::to_string(yres) +
         "]\n"
         "Sampler \"stratified\" \"integer xsamples\" [2] \"integer ysamples\" [2]\n"
         "SurfaceIntegrator \"directlighting\"\n"
         "WorldBegin\n"
         "LightSource \"point\" \"point from\" [0 0 -10] \"rgb I\" [100 100 100]\n"
         "Material \"matte\" \"rgb Kd\" [1 1 1]\n"
         "AttributeBegin\n Translate " +
         translate +
         "\n Shape \"sphere\" \"float radius\" [1]\n"
         "AttributeEnd\nWorldEnd\n";
}

TEST(PbrtConventions, PlusXIsRightAndPlusYIsUp) {
  auto right = test::renderSceneText(sceneWithSphereAt("3 0 0", 32, 32));
  EXPECT_GT(energy(right.film(), 16, 32, 0, 32), 0);
  EXPECT_EQ(energy(right.film(), 0, 16, 0, 32), 0);
  auto up = test::renderSceneText(sceneWithSphereAt("0 3 0", 32, 32));
  EXPECT_GT(energy(up.film(), 0, 32, 0, 16), 0);  // raster y grows downward
  EXPECT_EQ(energy(up.film(), 0, 32, 16, 32), 0);
}

TEST(PbrtConventions, FovSpansTheShorterImageAxis) {
  // A sphere of radius 1 at distance 10 subtends asin(0.1) = 5.74 degrees each side. With fov
  // 11.4 along the shorter (vertical) axis of a 64x32 image it just fits the height: it touches
  // nearly every row but covers only about half of the width.
  auto r = test::renderSceneText(sceneWithSphereAt("0 0 0", 64, 32, "11.6"));
  int rowsLit = 0, colsLit = 0;
  for (int y = 0; y < 32; ++y) rowsLit += energy(r.film(), 0, 64, y, y + 1) > 0;
  for (int x = 0; x < 64; ++x) colsLit += energy(r.film(), x, x + 1, 0, 32) > 0;
  EXPECT_GE(rowsLit, 30);
  EXPECT_LE(colsLit, 36);
  EXPECT_GE(colsLit, 28);
}

}  // namespace
}  // namespace candela
