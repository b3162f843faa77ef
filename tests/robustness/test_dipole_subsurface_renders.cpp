// "dipolesubsurface" (pbrt 2e §16.5) through the renderer: translucent spheres render finite and
// the same bits for 1 and 2 threads; a kdsubsurface sphere under a uniform sky returns Kd of it; a
// scene without subsurface materials is told so and renders as "directlighting"; pbrt-v2's
// ss-envmap example renders.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "core/error.h"

#include "support/render_scene.h"

namespace candela {
namespace {

std::string sphereScene(const std::string& integrator, const std::string& material,
                        const std::string& light, int resolution = 24) {
  return "LookAt 0 0 -5  0 0 0  0 1 0\n"
         "Camera \"perspective\" \"float fov\" [30]\n"
         "Film \"image\" \"integer xresolution\" [" +
         std::to_string(resolution) + "] \"integer yresolution\" [" + std::to_string(resolution) +
         "]\n"
         "Sampler \"random\" \"integer pixelsamples\" [2]\n"
         "SurfaceIntegrator " +
         integrator + "\nWorldBegin\n" + light + "\nMaterial " + material +
         "\nShape \"sphere\" \"float radius\" [1]\nWorldEnd\n";
}

const char* kPointLight = "LightSource \"point\" \"point from\" [2 2 -3] \"rgb I\" [10 10 10]";
const char* kSkin = "\"subsurface\" \"string name\" \"Skin1\" \"float scale\" [10]";

ImageBuffer render(const std::string& scene, int threads, std::string* warnings = nullptr) {
  test::TestRenderOptions o;
  o.build.nThreads = threads;
  o.render.nThreads = threads;
  if (warnings)
    o.build.warn = [warnings](const FileLoc&, const std::string& m) { *warnings += m + "\n"; };
  return test::renderSceneText(scene, o).film().image();
}

double meanOf(const ImageBuffer& img, int c) {
  double sum = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) sum += img.at(x, y, c);
  return sum / (img.width * img.height);
}

TEST(DipoleSubsurfaceRenders, FiniteAndDeterministicForOneAndTwoThreads) {
  std::string scene =
      sphereScene("\"dipolesubsurface\" \"float minsampledistance\" [0.1]", kSkin, kPointLight);
  ImageBuffer one = render(scene, 1), two = render(scene, 2);
  ASSERT_EQ(one.data.size(), two.data.size());
  for (float v : one.data) ASSERT_TRUE(std::isfinite(v));
  EXPECT_EQ(0, std::memcmp(one.data.data(), two.data.data(), one.data.size() * sizeof(float)));
  // The surface BSDF alone is a smooth dielectric that never reflects a point light toward the
  // camera: "directlighting" sees black, the dipole sees the light that went in.
  ImageBuffer direct = render(sphereScene("\"directlighting\"", kSkin, kPointLight), 2);
  EXPECT_EQ(meanOf(direct, 0), 0);
  EXPECT_GT(meanOf(one, 0), 1e-3);
  // Skin scatters red furthest and absorbs blue most.
  EXPECT_GT(meanOf(one, 0), meanOf(one, 2));
}

// The central 4 x 4 pixels of a 16 x 16 render, where the sphere faces the camera, against
// (1 - Fdr) Kd for Kd (.2 .5 .8) and eta 1 (see below).
void expectCentreIsKd(const ImageBuffer& img) {
  const double kd[3] = {0.2, 0.5, 0.8};
  for (int c = 0; c < 3; ++c) {
    double sum = 0;
    for (int y = 6; y < 10; ++y)
      for (int x = 6; x < 10; ++x) sum += img.at(x, y, c);
    double mean = sum / 16, expected = 0.9984 * kd[c];
    // Curvature, the point spacing and the irradiance samples: within 5 %.
    EXPECT_NEAR(mean, expected, 0.05 * expected) << "channel " << c;
  }
}

TEST(DipoleSubsurfaceRenders, KdSubsurfaceUnderAUniformSkyReturnsKd) {
  // eta 1: no specular reflection, Fdr = 0.0016. A sphere much larger than the mean free path
  // under a sky of radiance 1 is nearly a lit half-space: E = pi everywhere, and the dipole
  // returns Lo = (1 - Fdr) Kd E / pi = 0.9984 Kd.
  std::string scene =
      sphereScene("\"dipolesubsurface\" \"float minsampledistance\" [0.03]",
                  "\"kdsubsurface\" \"rgb Kd\" [.2 .5 .8] \"float meanfreepath\" [0.05] "
                  "\"float index\" [1]",
                  "LightSource \"infinite\" \"rgb L\" [1 1 1] \"integer nsamples\" [16]", 16);
  ImageBuffer img = render(scene, 0);
  expectCentreIsKd(img);
}

// A file in a fresh temporary directory, removed with it.
class TempFile {
 public:
  TempFile(const std::string& name, const std::string& text) {
    dir_ = std::filesystem::temp_directory_path() /
           ("candela-dipole-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
    path_ = (dir_ / name).string();
    std::ofstream(path_) << text;
  }
  ~TempFile() { std::filesystem::remove_all(dir_); }
  const std::string& path() const { return path_; }

 private:
  std::filesystem::path dir_;
  std::string path_;
};

// pbrt-v2's pointsfile: the same sky test with the points given instead of placed — a Fibonacci
// lattice on the unit sphere, each point a 1/n share of its area, eight numbers per point
// (position, normal, area, ray offset) with comments and commas as pbrt-v2's reader allows.
TEST(DipoleSubsurfaceRenders, PointsFromAPointsFileUnderAUniformSkyReturnKd) {
  const int n = 12000;
  std::ostringstream points;
  points.precision(9);
  points << "# x y z nx ny nz area offset\n";
  const double golden = kPi * (3 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    double z = 1 - (i + 0.5) * 2 / n, r = std::sqrt(1 - z * z), phi = golden * i;
    double x = r * std::cos(phi), y = r * std::sin(phi);
    points << x << " " << y << " " << z << ", " << x << " " << y << " " << z << " " << 4 * kPi / n
           << " 1e-4\n";
  }
  TempFile file("sphere points.txt", points.str());
  std::string warnings;
  test::TestRenderOptions o;
  o.build.warn = [&](const FileLoc&, const std::string& m) { warnings += m + "\n"; };
  auto r = test::renderSceneText(
      sphereScene("\"dipolesubsurface\" \"string pointsfile\" \"" + file.path() + "\"",
                  "\"kdsubsurface\" \"rgb Kd\" [.2 .5 .8] \"float meanfreepath\" [0.05] "
                  "\"float index\" [1]",
                  "LightSource \"infinite\" \"rgb L\" [1 1 1] \"integer nsamples\" [16]", 16),
      o);
  EXPECT_EQ(warnings, "");
  std::string stats = r.job().integrator->statsReport();
  EXPECT_NE(stats.find("sample points  12000 (from " + file.path() + ")"), std::string::npos)
      << stats;
  ImageBuffer img = r.film().image();
  expectCentreIsKd(img);
  // The points are what lights the sphere: a file holding only the far side's leaves the
  // centre dark.
  std::ostringstream far;
  far.precision(9);
  for (int i = 0; i < n; ++i) {
    double z = 1 - (i + 0.5) * 2 / n, rr = std::sqrt(1 - z * z), phi = golden * i;
    if (z < 0.5) continue;  // the camera looks along +z from z = -5: keep the back only
    far << rr * std::cos(phi) << " " << rr * std::sin(phi) << " " << z << " " << rr * std::cos(phi)
        << " " << rr * std::sin(phi) << " " << z << " " << 4 * kPi / n << " 1e-4\n";
  }
  TempFile farFile("far.txt", far.str());
  ImageBuffer dark =
      test::renderSceneText(
          sphereScene("\"dipolesubsurface\" \"string pointsfile\" \"" + farFile.path() + "\"",
                      "\"kdsubsurface\" \"rgb Kd\" [.2 .5 .8] \"float "
                      "meanfreepath\" [0.05] \"float index\" [1]",
                      "LightSource \"infinite\" \"rgb L\" [1 1 1]", 16))
          .film()
          .image();
  EXPECT_LT(dark.at(8, 8, 2), 0.01);
}

// Bad pointsfiles: located errors that say what is wrong with which file.
TEST(DipoleSubsurfaceRenders, BadPointsFilesAreLocatedErrors) {
  struct Case {
    std::string text, mentions;
  };
  for (const Case& c : std::vector<Case>{{"0 0 0 0 0 1 0.1", "multiple of 8"},
                                         {"0 0 0  0 0 0  0.1 0", "zero normal"},
                                         {"0 0 0  0 0 1  -0.1 0", "negative area"},
                                         {"0 0 0  0 0 1  0.1 x", "line 1: expected a number"},
                                         {"# nothing\n", "no points"}}) {
    TempFile file("points.txt", c.text);
    std::string scene =
        sphereScene("\"dipolesubsurface\"\n  \"string pointsfile\" \"" + file.path() + "\"", kSkin,
                    kPointLight);
    try {
      test::buildSceneText(scene);
      ADD_FAILURE() << "no error for " << c.text;
    } catch (const SceneError& e) {
      EXPECT_EQ(e.location().line, 6) << e.what();
      EXPECT_NE(std::string(e.what()).find(c.mentions), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(file.path()), std::string::npos) << e.what();
    }
  }
}

TEST(DipoleSubsurfaceRenders, WithoutSubsurfaceMaterialsItWarnsAndIsDirectLighting) {
  std::string warnings;
  std::string matte = "\"matte\" \"rgb Kd\" [.5 .5 .5]";
  ImageBuffer dipole =
      render(sphereScene("\"dipolesubsurface\"", matte, kPointLight), 2, &warnings);
  EXPECT_NE(warnings.find("dipolesubsurface"), std::string::npos) << warnings;
  EXPECT_NE(warnings.find("directlighting"), std::string::npos) << warnings;
  ImageBuffer direct = render(sphereScene("\"directlighting\"", matte, kPointLight), 2);
  ASSERT_EQ(dipole.data.size(), direct.data.size());
  EXPECT_EQ(
      0, std::memcmp(dipole.data.data(), direct.data.data(), dipole.data.size() * sizeof(float)));
  EXPECT_GT(meanOf(direct, 0), 1e-3);
}

TEST(DipoleSubsurfaceRenders, PbrtV2SsEnvmapRendersSmall) {
  namespace fs = std::filesystem;
  std::string dir = std::string(CANDELA_SHARED_SCENES_DIR) + "/pbrt-v2";
  std::ifstream in(dir + "/ss-envmap.pbrt");
  if (!in) GTEST_SKIP() << "shared scenes not found: " << dir;
  std::stringstream text;
  text << in.rdbuf();
  std::string scene = text.str();
  auto replace = [&](const std::string& from, const std::string& to) {
    for (size_t at = scene.find(from); at != std::string::npos;
         at = scene.find(from, at + to.size()))
      scene.replace(at, from.size(), to);
  };
  // Small: 16 x 16 pixels, and the scene's relative paths made absolute (the text has no file).
  replace("[500]", "[16]");
  replace("\"textures/", "\"" + dir + "/textures/");
  replace("\"geometry/", "\"" + dir + "/geometry/");
  test::TestRenderOptions o;
  o.build.sppOverride = 1;
  o.build.quick = true;  // a quarter of the preprocess's light samples
  int loads = 0;
  // The image textures as a mid-grey 4 x 4 image: this test is about the integrator.
  o.build.loadImage = [&](const std::string&, const std::string&) {
    ++loads;
    ImageBuffer img(4, 4, {"R", "G", "B"});
    for (float& v : img.data) v = 0.5f;
    return img;
  };
  auto r = test::renderSceneText(scene, o);
  EXPECT_GE(loads, 1);
  ImageBuffer img = r.film().image();
  double sum = 0;
  for (float v : img.data) {
    ASSERT_TRUE(std::isfinite(v));
    sum += v;
  }
  EXPECT_GT(sum, 0);
  EXPECT_NE(r.job().integrator->statsReport().find("sample points"), std::string::npos);
}

}  // namespace
}  // namespace candela
