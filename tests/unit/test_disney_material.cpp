// The "disney" material through the scene path: every parameter parses (constants and
// textures), the scene renders finite, subsurface scattering it cannot do is a located warning,
// misspelt parameters are reported unused, and bad values are located errors.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/error.h"
#include "support/render_scene.h"

namespace candela {
namespace {

// A pbrt-v3 scene whose disney material statement has `params` from line 9 on, one per line.
std::string scene(const std::vector<std::string>& params) {
  std::string s =
      "Film \"image\" \"integer xresolution\" [8] \"integer yresolution\" [8]\n"  // 1
      "Sampler \"random\" \"integer pixelsamples\" [8]\n"                         // 2
      "Integrator \"path\"\n"                                                     // 3
      "LookAt 0 0 5 0 0 0 0 1 0\n"                                                // 4
      "Camera \"perspective\" \"float fov\" [30]\n"                               // 5
      "WorldBegin\n"                                                              // 6
      "LightSource \"infinite\" \"rgb L\" [1 1 1]\n"                              // 7
      "Texture \"checks\" \"float\" \"checkerboard\" \"float tex1\" [0.1] \"float tex2\" "
      "[0.9]\n"                 // 8
      "Material \"disney\"\n";  // 9
  for (const std::string& p : params) s += "  " + p + "\n";
  return s + "Shape \"sphere\"\nWorldEnd\n";
}

const std::vector<std::string> kEveryParameter = {
    "\"rgb color\" [0.8 0.3 0.2]",            // line 10
    "\"float metallic\" [0.3]",               // 11
    "\"float eta\" [1.45]",                   // 12
    "\"texture roughness\" \"checks\"",       // 13
    "\"float speculartint\" [0.4]",           // 14
    "\"float anisotropic\" [0.5]",            // 15
    "\"float sheen\" [0.6]",                  // 16
    "\"float sheentint\" [0.2]",              // 17
    "\"float clearcoat\" [0.7]",              // 18
    "\"float clearcoatgloss\" [0.3]",         // 19
    "\"float spectrans\" [0.4]",              // 20
    "\"rgb scatterdistance\" [0.5 0.2 0.1]",  // 21
    "\"bool thin\" \"false\"",                // 22
    "\"float flatness\" [0.5]",               // 23
    "\"float difftrans\" [1.3]",              // 24
    "\"texture bumpmap\" \"checks\"",         // 25
};

struct Warning {
  FileLoc loc;
  std::string text;
};

std::vector<Warning> warningsOf(const std::string& text, std::vector<float>* image = nullptr) {
  std::vector<Warning> w;
  test::TestRenderOptions o;
  o.build.warn = [&](const FileLoc& loc, const std::string& s) { w.push_back({loc, s}); };
  auto r = test::renderSceneText(text, o);
  if (image) *image = r.film().image().data;
  return w;
}

TEST(DisneyMaterial, EveryParameterParsesAndRendersFinite) {
  std::vector<float> image;
  std::vector<Warning> w = warningsOf(scene(kEveryParameter), &image);
  ASSERT_FALSE(image.empty());
  double sum = 0;
  for (float v : image) {
    EXPECT_TRUE(std::isfinite(v));
    EXPECT_GE(v, 0);
    sum += v;
  }
  EXPECT_GT(sum, 0);
  // Only the subsurface warning, at scatterdistance: every other parameter was used.
  ASSERT_EQ(w.size(), 1u) << (w.empty() ? "" : w[0].text);
  EXPECT_EQ(w[0].loc.line, 21);
  EXPECT_NE(w[0].text.find("scatterdistance"), std::string::npos) << w[0].text;
}

TEST(DisneyMaterial, ThinAndDefaultSurfacesDoNotWarn) {
  // Thin surfaces ignore scatterdistance (as pbrt-v3 does), and 0 asks for no subsurface.
  EXPECT_TRUE(warningsOf(scene({"\"bool thin\" \"true\"", "\"rgb scatterdistance\" [1 1 1]",
                                "\"float spectrans\" [0.5]"}))
                  .empty());
  EXPECT_TRUE(warningsOf(scene({"\"rgb scatterdistance\" [0 0 0]"})).empty());
  EXPECT_TRUE(warningsOf(scene({})).empty());
}

TEST(DisneyMaterial, MisspeltParameterIsReportedUnused) {
  std::vector<Warning> w = warningsOf(scene({"\"float metalic\" [1]"}));
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].loc.line, 10);
  EXPECT_NE(w[0].text.find("metalic"), std::string::npos) << w[0].text;
}

TEST(DisneyMaterial, BadValuesAreLocatedErrors) {
  const char* bad[] = {"\"float metallic\" [1.5]",
                       "\"float roughness\" [-0.1]",
                       "\"float eta\" [0]",
                       "\"float eta\" [-1.5]",
                       "\"float difftrans\" [2.5]",
                       "\"rgb scatterdistance\" [1 -1 1]",
                       "\"rgb color\" [0.5 -0.2 0.5]",
                       "\"float clearcoatgloss\" [2]",
                       "\"float sheen\" [-1]",
                       "\"float spectrans\" [1.01]",
                       "\"float flatness\" [3]",
                       "\"float anisotropic\" [-0.5]",
                       "\"float speculartint\" [9]",
                       "\"float sheentint\" [-2]",
                       "\"float clearcoat\" [1.5]",
                       "\"texture roughness\" \"nosuch\"",
                       "\"float metallic\" [0.1 0.2]"};
  for (const char* b : bad) {
    SCOPED_TRACE(b);
    std::string name = std::string(b).substr(std::string(b).find(' ') + 1);
    name = name.substr(0, name.find('"'));
    try {
      test::buildSceneText(scene({"\"float metallic\" [0]", b}));
      ADD_FAILURE() << "no error";
    } catch (const SceneError& e) {
      EXPECT_EQ(e.location().line, 11) << e.what();
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
}

TEST(DisneyMaterial, AvailableInPbrtV2Scenes) {
  // No pbrt-v2 material has the name: a scene without pbrt-v3 statements gets it too.
  std::string s = scene({"\"float metallic\" [1]"});
  s.replace(s.find("Integrator \"path\""), 17, "SurfaceIntegrator \"path\"");
  std::vector<float> image;
  EXPECT_TRUE(warningsOf(s, &image).empty());
  for (float v : image) EXPECT_TRUE(std::isfinite(v));
}

}  // namespace
}  // namespace candela
