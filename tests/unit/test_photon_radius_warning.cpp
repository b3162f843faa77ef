// pbrt-v2's photon search radius ("maxdist", 0.1) is absolute: the photon map integrator keeps it
// but measures it against the photons shot, and warns at the integrator's statement, with a radius
// that would do, when lookups find under a quarter of the "nused" photons an estimate wants. The
// same room at a scale of 1 is fine as given; at 555 (the Cornell box's units) it is not, and the
// suggested radius is.
#include <gtest/gtest.h>

#include <regex>

#include "support/render_scene.h"

namespace candela {
namespace {

std::string room(double scale, const std::string& maxdist = "") {
  return "LookAt 0 0.5 1.9  0 0.5 0  0 1 0\nCamera \"perspective\" \"float fov\" [50]\n"
         "Film \"image\" \"integer xresolution\" [8] \"integer yresolution\" [8]\n"
         "SurfaceIntegrator \"photonmap\" \"integer indirectphotons\" [20000] "
         "\"integer causticphotons\" [0] \"bool finalgather\" \"false\"" +
         maxdist + "\nWorldBegin\nScale " + std::to_string(scale) + " " + std::to_string(scale) +
         " " + std::to_string(scale) +
         "\nLightSource \"point\" \"point from\" [0 0.9 0] \"rgb I\" [2 2 2]\n"
         "Material \"matte\" \"rgb Kd\" [0.7 0.7 0.7]\n"
         "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3  4 6 5 4 7 6  0 4 5 0 5 1]\n"
         "  \"point P\" [-1 0 -1  1 0 -1  1 0 1  -1 0 1  -1 1 -1  1 1 -1  1 1 1  -1 1 1]\n"
         "WorldEnd\n";
}

std::vector<std::pair<FileLoc, std::string>> warningsOf(const std::string& text) {
  std::vector<std::pair<FileLoc, std::string>> w;
  BuildOptions o;
  o.seed = 3;
  o.warn = [&](const FileLoc& loc, const std::string& s) {
    if (s.find("maxdist") != std::string::npos) w.push_back({loc, s});
  };
  test::buildSceneText(text, o);
  return w;
}

TEST(PhotonSearchRadius, AnAbsoluteRadiusTooSmallForTheSceneIsALocatedWarningWithAValue) {
  EXPECT_TRUE(warningsOf(room(1)).empty());
  auto w = warningsOf(room(555));
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].first.line, 4);  // the SurfaceIntegrator statement
  EXPECT_NE(w[0].second.find("\"maxdist\" 0.1 (the photon search radius, absolute) finds "),
            std::string::npos)
      << w[0].second;
  EXPECT_NE(w[0].second.find("of the 50 (\"nused\")"), std::string::npos) << w[0].second;
  std::smatch m;
  std::string message = w[0].second;
  ASSERT_TRUE(std::regex_search(message, m, std::regex("\"float maxdist\" \\[([0-9.e+]+)\\]")))
      << message;
  double suggested = std::stod(m[1]);
  // The room's floor is 1110 units wide; 20,000 photons over its three walls leave about 60 per
  // 10 x 10 units: 50 of them lie within some tens of units.
  EXPECT_GT(suggested, 5);
  EXPECT_LT(suggested, 100);
  EXPECT_TRUE(warningsOf(room(555, " \"float maxdist\" [" + std::string(m[1]) + "]")).empty());
}

}  // namespace
}  // namespace candela
