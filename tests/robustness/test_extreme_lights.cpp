// Extreme lights (issue 15): a sphere light of radius 1e-5 and radiance 1e10, and a point light of
// intensity 1e6 1e-4 above a plane (tests/robustness/scenes). Each image is finite, no sample
// is dropped as non-finite, and every pixel is the closed form of a plane under a point light
// (plane_under_light.h) within 5 standard errors, under the integrators that sample the light.
// Both scenes are the same picture as huge-plane.pbrt at other scales and intensities, with the
// same samples: they measure the same worst pixel when all three are right.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "plane_under_light.h"
#include "scene_files.h"
#include "support/render_scene.h"
#include "support/robustness_figures.h"

namespace candela {
namespace {

// The scene under directlighting, path and volpath against the closed form; records the worst
// pixel, in standard errors, under the criterion.
void checkUnderEachIntegrator(const std::string& scene, const test::PlaneUnderLight& light,
                              const std::string& criterion) {
  double worst = 0;
  for (const char* integrator : {"SurfaceIntegrator \"directlighting\"",
                                 "SurfaceIntegrator \"path\"", "Integrator \"volpath\""}) {
    std::string text = test::robustnessScene(scene);
    test::replaceOnce(&text, "SurfaceIntegrator \"directlighting\"", integrator);
    test::RenderedScene r = test::renderSceneText(text);
    EXPECT_EQ(r.results.front().nonFiniteSamples, 0u) << integrator;
    worst = std::max(worst,
                     test::worstPixelAgainstClosedForm(r.film(), light, scene + ", " + integrator));
  }
  test::recordFigure(criterion +
                         " (directlighting, path, volpath): finite, every pixel within 5 "
                         "standard errors of the closed form",
                     "finite; worst pixel %.2f standard errors", worst);
}

TEST(ExtremeLights, ASphereLightOfRadiusOneHundredThousandthAndRadiance1e10GivesTheClosedForm) {
  test::PlaneUnderLight light;
  light.intensity = M_PI * 1e10 * 1e-5 * 1e-5;  // pi L r^2
  checkUnderEachIntegrator("tiny-sphere-light.pbrt", light,
                           "sphere light radius 1e-5, L 1e10, 1 above a plane");
}

TEST(ExtremeLights, APointLightOfIntensity1e6OneTenThousandthAboveAPlaneGivesTheClosedForm) {
  test::PlaneUnderLight light;
  light.intensity = 1e6;
  light.height = 1e-4;
  light.halfWidth = 2e-4;
  checkUnderEachIntegrator("bright-point-light.pbrt", light,
                           "point light I 1e6, 1e-4 above a plane (radiance to 1.6e13)");
}

}  // namespace
}  // namespace candela
