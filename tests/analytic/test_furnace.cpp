// Furnace tests (lrt draft §16.2's closed-form interior of a closed diffuse sphere): the camera
// sits inside a unit sphere whose normals face inward, so every pixel sees the same analytic
// value. Each test checks every pixel of a 16x16 image.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/render_scene.h"

namespace candela {
namespace {

std::string furnaceScene(const std::string& integrator, const std::string& world, int spp) {
  return "LookAt 0 0 0  0 0 1  0 1 0\n"
         "Camera \"perspective\" \"float fov\" [60]\n"
         "Film \"image\" \"integer xresolution\" [16] \"integer yresolution\" [16]\n"
         "Sampler \"random\" \"integer pixelsamples\" [" +
         std::to_string(spp) + "]\n" + "SurfaceIntegrator " + integrator + "\nWorldBegin\n" +
         world + "\nWorldEnd\n";
}

// Worst relative deviation of any pixel's channel from the expected value; alpha must be 1.
double worstRelativeError(const Film& film, double expected) {
  double worst = 0;
  Bounds2i b = film.pixelBounds();
  for (int y = b.pMin.y; y < b.pMax.y; ++y)
    for (int x = b.pMin.x; x < b.pMax.x; ++x) {
      Spectrum v = film.pixelValue(Point2i(x, y));
      EXPECT_EQ(film.pixelAlpha(Point2i(x, y)), 1.f);
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(v[c] - expected) / expected);
    }
  return worst;
}

const char* kEmissiveSphere =
    "Material \"matte\" \"rgb Kd\" [0.5 0.5 0.5]\n"
    "AreaLightSource \"diffuse\" \"rgb L\" [0.5 0.5 0.5]\n"
    "ReverseOrientation\n"
    "Shape \"sphere\" \"float radius\" [1]\n";

TEST(Furnace, PathEmissionConvergesToGeometricSeries) {
  // L = Le / (1 - rho) = 0.5 / (1 - 0.5) = 1 once every bounce is counted (Russian roulette
  // terminates the paths). Russian roulette makes this the noisiest case: 8192 spp puts 1% at
  // about 5 standard deviations of a pixel.
  auto r = test::renderSceneText(
      furnaceScene("\"path\" \"integer maxdepth\" [1000]", kEmissiveSphere, 8192));
  EXPECT_LT(worstRelativeError(r.film(), 1.0), 0.01);
}

TEST(Furnace, PathMaxDepthTruncatesTheSeries) {
  // With at most d reflections: L = 0.5 * sum_{i=0..d} 0.5^i = 1 - 0.5^(d+1).
  for (int d = 1; d <= 4; ++d) {
    auto r = test::renderSceneText(furnaceScene(
        "\"path\" \"integer maxdepth\" [" + std::to_string(d) + "]", kEmissiveSphere, 128));
    double expected = 1 - std::pow(0.5, d + 1);
    EXPECT_LT(worstRelativeError(r.film(), expected), 0.01) << "maxdepth " << d;
  }
}

TEST(Furnace, DirectLightingPointLightAtCentre) {
  // E = I / r^2 = pi at every wall point, so L = (Kd / pi) * pi = Kd = 0.5, with no noise.
  const char* world =
      "LightSource \"point\" \"rgb I\" [3.14159265 3.14159265 3.14159265]\n"
      "Material \"matte\" \"rgb Kd\" [0.5 0.5 0.5]\n"
      "ReverseOrientation\n"
      "Shape \"sphere\" \"float radius\" [1]\n";
  for (const char* strategy : {"all", "one"}) {
    auto r = test::renderSceneText(furnaceScene(
        std::string("\"directlighting\" \"string strategy\" \"") + strategy + "\"", world, 4));
    EXPECT_LT(worstRelativeError(r.film(), 0.5), 0.01) << strategy;
  }
}

TEST(Furnace, DirectLightingOfEmittingSphereIsOneBounce) {
  // Emission seen directly plus one reflection of the uniformly lit interior: 0.5 + 0.5 * 0.5.
  auto r = test::renderSceneText(furnaceScene("\"directlighting\"", kEmissiveSphere, 64));
  EXPECT_LT(worstRelativeError(r.film(), 0.75), 0.01);
}

}  // namespace
}  // namespace candela
