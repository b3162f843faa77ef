// Bump mapping through the integrators: the cosine of the rendering equation is taken against the
// bumped shading normal (pbrt 2e's dgShading.nn), not the surface's. A plane z = 0 with uv = (x, y)
// and the bump d = a u (a "bilerp" texture) has the bumped normal (-a, 0, 1) / sqrt(1 + a^2),
// tilted by atan(a) = 30 degrees here.
#include <gtest/gtest.h>

#include <cmath>

#include "support/render_scene.h"

namespace candela {
namespace {

const double kSlope = std::tan(kPi / 6);  // a: a 30-degree tilt

std::string plane(const std::string& material, bool bumped) {
  std::string s = std::string("Texture \"ramp\" \"float\" \"bilerp\" \"float v00\" [0] ")
                      .append("\"float v01\" [0] \"float v10\" [")
                      .append(std::to_string(kSlope))
                      .append("] \"float v11\" [")
                      .append(std::to_string(kSlope))
                      .append("]\n")
                      .append(material);
  if (bumped) s.append(" \"texture bumpmap\" \"ramp\"");
  return s.append(
      "\nShape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3]\n"
      "  \"point P\" [0 0 0  1 0 0  1 1 0  0 1 0] \"float uv\" [0 0  1 0  1 1  0 1]\n");
}

// The value at the centre of the plane, seen straight down through a tiny orthographic window.
float centre(const std::string& integrator, const std::string& world) {
  std::string scene = std::string("LookAt 0.5 0.5 3  0.5 0.5 0  0 1 0\n")
                          .append(
                              "Camera \"orthographic\" \"float screenwindow\" [-1e-3 1e-3 "
                              "-1e-3 1e-3]\n")
                          .append(
                              "Film \"image\" \"integer xresolution\" [1] \"integer "
                              "yresolution\" [1]\n")
                          .append(
                              "Sampler \"stratified\" \"integer xsamples\" [2] \"integer "
                              "ysamples\" [2]\n")
                          .append("PixelFilter \"box\"\nSurfaceIntegrator ")
                          .append(integrator)
                          .append("\nWorldBegin\n")
                          .append(world)
                          .append("WorldEnd\n");
  return test::renderSceneText(scene).film().pixelValue(Point2i(0, 0))[1];
}

TEST(BumpScenes, BumpedMirrorUnderAUniformSkyReflectsItExactly) {
  // Kr = 1 under L = 1 is 1 whatever the normal; with the unbumped normal in the cosine it was
  // 1 / cos 30 = 1.1547.
  std::string world = "LightSource \"infinite\" \"rgb L\" [1 1 1]\n" +
                      plane("Material \"mirror\" \"rgb Kr\" [1 1 1]", true);
  for (const char* integrator : {"\"whitted\"", "\"directlighting\"", "\"path\""})
    EXPECT_NEAR(centre(integrator, world), 1, 1e-5) << integrator;
}

TEST(BumpScenes, BumpedMattePlaneTakesTheTiltedCosine) {
  // A point light of intensity I straight above at height h: Kd / pi * I / h^2 * cos(30).
  const double kd = 0.5, intensity = 4, h = 2;
  std::string light = "LightSource \"point\" \"point from\" [0.5 0.5 2] \"rgb I\" [4 4 4]\n";
  std::string matte = "Material \"matte\" \"rgb Kd\" [0.5 0.5 0.5]";
  double flat = kd / kPi * intensity / (h * h);
  for (const char* integrator : {"\"whitted\"", "\"directlighting\"", "\"path\""}) {
    EXPECT_NEAR(centre(integrator, light + plane(matte, false)), flat, 1e-5 * flat) << integrator;
    EXPECT_NEAR(centre(integrator, light + plane(matte, true)), flat * std::cos(kPi / 6),
                1e-4 * flat)
        << integrator;
  }
}

}  // namespace
}  // namespace candela
