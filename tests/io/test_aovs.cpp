// AOV layers round-trip through OpenEXR with the names compositing tools read, and hold the
// closed-form values of a unit sphere seen head-on.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "film/output/image_output.h"
#include "support/render_scene.h"

namespace candela {
namespace {

TEST(Aovs, SphereLayersRoundTripWithAnalyticValues) {
  // Camera at z = -5 looking at a unit sphere at the origin; orthographic-like narrow fov.
  const std::string scene =
      "LookAt 0 0 -5  0 0 0  0 1 0\n"
      "Camera \"perspective\" \"float fov\" [30]\n"
      "Film \"image\" \"integer xresolution\" [32] \"integer yresolution\" [32]\n"
      "  \"string aovs\" \"albedo,normal,depth\"\n"
      "Sampler \"stratified\" \"integer xsamples\" [2] \"integer ysamples\" [2]\n"
      "SurfaceIntegrator \"directlighting\"\n"
      "WorldBegin\n"
      "LightSource \"point\" \"point from\" [0 0 -5] \"rgb I\" [10 10 10]\n"
      "Material \"matte\" \"rgb Kd\" [0.2 0.4 0.6]\n"
      "Shape \"sphere\" \"float radius\" [1]\n"
      "WorldEnd\n";
  test::TestRenderOptions o;
  o.build.aovs = kAovPosition | kAovVariance | kAovSamples;  // added to the film's list
  auto r = test::renderSceneText(scene, o);
  ImageBuffer img = r.film().image();

  auto dir = std::filesystem::temp_directory_path() / "candela-aov-test";
  std::filesystem::create_directories(dir);
  std::string path = (dir / "aov.exr").string();
  writeExr(path, img, {});
  ImageBuffer back = readImage(path);
  std::filesystem::remove_all(dir);

  for (const char* ch :
       {"R", "G", "B", "A", "albedo.R", "albedo.G", "albedo.B", "N.X", "N.Y", "N.Z", "Z", "P.X",
        "P.Y", "P.Z", "variance.R", "variance.G", "variance.B", "samples"})
    ASSERT_GE(back.channelIndex(ch), 0) << ch;
  auto at = [&](int x, int y, const char* ch) { return back.at(x, y, back.channelIndex(ch)); };

  // The centre pixel sees the sphere's nearest point (0, 0, -1): normal (0, 0, -1), depth 4.
  int covered = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      if (at(x, y, "A") < 1) continue;  // the silhouette's pixels are partly background
      ++covered;
      Vector3f p(at(x, y, "P.X"), at(x, y, "P.Y"), at(x, y, "P.Z"));
      Vector3f n(at(x, y, "N.X"), at(x, y, "N.Y"), at(x, y, "N.Z"));
      // The normal of a unit sphere is its position; averaged over a pixel, to within the angle
      // a pixel spans at the sphere (~0.06 rad here at the worst, near the silhouette).
      EXPECT_NEAR(n.length(), 1, 1e-3);
      EXPECT_GT(dot(normalize(p), n), 0.99) << x << "," << y;
      EXPECT_NEAR(at(x, y, "albedo.R"), 0.2, 1e-4);
      EXPECT_NEAR(at(x, y, "albedo.G"), 0.4, 1e-4);
      EXPECT_NEAR(at(x, y, "albedo.B"), 0.6, 1e-4);
      EXPECT_EQ(at(x, y, "samples"), 4);
      // Camera rays start on the near plane (hither 1e-3), and Z is measured from there.
      EXPECT_GE(at(x, y, "Z"), 4 - 1e-3 - 1e-4);
    }
  EXPECT_GT(covered, 100);
  EXPECT_NEAR(at(16, 16, "Z"), 4, 0.01);
  EXPECT_NEAR(at(16, 16, "N.Z"), -1, 0.01);
  EXPECT_TRUE(std::isinf(at(0, 0, "Z")));  // background
  EXPECT_EQ(at(0, 0, "N.X"), 0);
}

TEST(Aovs, UnknownNameListsTheKnownOnes) {
  try {
    parseAovList("albedo, nromal", FileLoc{"x.pbrt", 3, 7});
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("x.pbrt:3:7"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("'nromal'"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("normal"), std::string::npos);
  }
  EXPECT_EQ(parseAovList(" albedo ,depth,", FileLoc{}), unsigned(kAovAlbedo | kAovDepth));
}

}  // namespace
}  // namespace candela
