// Lights through scene files: a diffuse plane under a uniform sky (infinite light) renders ρ L
// with the path integrator (E = π L on the plane, L_out = ρ E / π); every light name builds with
// pbrt-v2's parameters; spectral inputs ("spectrum" inline and .spd, "blackbody", "xyz") reach a
// light as the RGB the spectrum converter gives.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "parser/spectrum_input.h"
#include "support/render_scene.h"

namespace candela {
namespace {

// Stratified 32 x 32 samples per pixel when spp > 1: the light and BSDF samples are stratified
// too, which the 1% bound on every pixel needs.
std::string frame(const std::string& integrator, int spp, const std::string& world) {
  std::string n = spp > 1 ? "32" : "1";
  return "LookAt 0 0 5  0 0 0  0 1 0\n"
         "Camera \"perspective\" \"float fov\" [30]\n"
         "Film \"image\" \"integer xresolution\" [4] \"integer yresolution\" [4]\n"
         "Sampler \"stratified\" \"integer xsamples\" [" +
         n + "] \"integer ysamples\" [" + n + "]\nSurfaceIntegrator " + integrator +
         "\nWorldBegin\n" + world + "\nWorldEnd\n";
}

const char* kPlane =
    "Material \"matte\" \"rgb Kd\" [0.5 0.5 0.5]\n"
    "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3]\n"
    "  \"point P\" [-1000 -1000 0  1000 -1000 0  1000 1000 0  -1000 1000 0]\n";

TEST(InfiniteLightScene, DiffusePlaneUnderUniformSkyRendersRhoL) {
  std::string world =
      std::string("LightSource \"infinite\" \"rgb L\" [2 2 2] \"integer nsamples\" [2]\n") + kPlane;
  test::RenderedScene r = test::renderSceneText(frame("\"path\"", 64, world));
  const Film& film = r.film();
  Bounds2i b = film.pixelBounds();
  double sum = 0;
  int n = 0;
  for (int y = b.pMin.y; y < b.pMax.y; ++y)
    for (int x = b.pMin.x; x < b.pMax.x; ++x, ++n) {
      Spectrum v = film.pixelValue(Point2i(x, y));
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(v[c], 1.0, 0.01) << x << "," << y;
      sum += v[1];
    }
  EXPECT_NEAR(sum / n, 1.0, 0.01);  // ρ L = 0.5 × 2
}

TEST(InfiniteLightScene, ExinfiniteIsPbrtV2sOtherNameForIt) {
  auto render = [](const char* name) {
    std::string world =
        std::string("LightSource \"").append(name).append("\" \"rgb L\" [2 2 2]\n") + kPlane;
    return test::renderSceneText(frame("\"path\"", 2, world)).film().image();
  };
  ImageBuffer a = render("infinite"), b = render("exinfinite");
  EXPECT_EQ(a.data, b.data);
}

Spectrum intensityAtUnitDistance(const Light& light) {
  Vector3f wi;
  Float pdf;
  VisibilityTester vis;
  return light.sampleLi(Interaction(Point3f(0, 0, 1), 0), Point2f(0.5f, 0.5f), &wi, &pdf, &vis);
}

TEST(LightFactory, EveryLightBuildsWithPbrtParameters) {
  std::string world =
      std::string(
          "LightSource \"point\" \"rgb I\" [1 1 1] \"point from\" [0 0 3]\n"
          "LightSource \"spot\" \"rgb I\" [1 1 1] \"point from\" [0 0 3] "
          "\"point to\" [0 0 0] \"float coneangle\" [20] \"float conedeltaangle\" [4]\n"
          "LightSource \"distant\" \"rgb L\" [1 1 1] \"point from\" [0 0 1] "
          "\"point to\" [0 0 0] \"rgb scale\" [0.5 0.5 0.5]\n"
          "LightSource \"projection\" \"rgb I\" [1 1 1] \"float fov\" [30]\n"
          "LightSource \"goniometric\" \"rgb I\" [1 1 1]\n"
          "LightSource \"infinite\" \"rgb L\" [0.1 0.1 0.1]\n") +
      kPlane;
  test::RenderedScene r = test::buildSceneText(frame("\"directlighting\"", 1, world));
  ASSERT_EQ(r.job().lights.size(), 6u);
  // The distant light's scale applies, and its power uses the scene's bounds from preprocess.
  const Light& distant = *r.job().lights[2];
  EXPECT_FLOAT_EQ(intensityAtUnitDistance(distant)[0], 0.5f);
  EXPECT_GT(distant.power()[0], 0.5f * kPi * 1000 * 1000);
  EXPECT_THROW(test::buildSceneText(frame("\"path\"", 1, "LightSource \"sun\"\n")), std::exception);
  EXPECT_THROW(test::buildSceneText(frame(
                   "\"path\"", 1, "LightSource \"infinite\" \"string mapname\" [\"sky.exr\"]\n")),
               std::exception);  // no image reader in this build
}

TEST(LightFactory, SpectralInputsBecomeRGB) {
  std::string spd = (std::filesystem::temp_directory_path() / "candela_lights_test.spd").string();
  {
    std::ofstream f(spd);
    f << "# lambda value\n400 1\n550 3\n700 1\n";
  }
  std::string world =
      "LightSource \"point\" \"spectrum I\" [400 2 700 2]\n"
      "LightSource \"point\" \"spectrum I\" \"" +
      spd +
      "\"\n"
      "LightSource \"point\" \"blackbody I\" [3000 2]\n"
      "LightSource \"point\" \"xyz I\" [0.3 0.4 0.5]\n";
  test::RenderedScene r = test::buildSceneText(frame("\"directlighting\"", 1, world));
  std::remove(spd.c_str());
  ASSERT_EQ(r.job().lights.size(), 4u);
  auto near = [](const Spectrum& a, const Spectrum& b) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 1e-4 * std::max(1.f, std::abs(b[c])));
  };
  Spectrum flat = intensityAtUnitDistance(*r.job().lights[0]);
  EXPECT_NEAR(flat.y(), 2, 2e-3);  // a constant SPD of 2 has Y = 2
  near(flat, spectrumSamplesToRGB({{400, 2}, {700, 2}}, SpectrumUse::Illuminant));
  near(intensityAtUnitDistance(*r.job().lights[1]),
       spectrumSamplesToRGB({{400, 1}, {550, 3}, {700, 1}}, SpectrumUse::Illuminant));
  Spectrum bb = intensityAtUnitDistance(*r.job().lights[2]);
  near(bb, blackbodyToRGB(3000, 2));
  EXPECT_GT(bb[0], bb[2]);  // 3000 K is reddish
  Float xyz[3];
  intensityAtUnitDistance(*r.job().lights[3]).toXYZ(xyz);
  EXPECT_NEAR(xyz[0], 0.3f, 1e-3);
  EXPECT_NEAR(xyz[1], 0.4f, 1e-3);
  EXPECT_NEAR(xyz[2], 0.5f, 1e-3);
}

}  // namespace
}  // namespace candela
