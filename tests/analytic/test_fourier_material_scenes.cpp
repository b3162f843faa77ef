// Material "fourier" in scenes: a plane under a uniform sky (infinite light L = 1) renders
// rho L with a Lambertian table of albedo rho, as "matte" with Kd = rho does (E = pi L, L_out =
// rho E / pi at every view angle, so every pixel expects the same value). Statistic: the mean of
// the green channel over the 8 x 8 pixels, with the standard error from the pixels' spread (the
// image is uniform in expectation, so the spread is noise); the two means must agree within 4
// combined standard errors and each with rho L within 4 of its own (a two-sided 6e-5 chance per
// comparison under the null). The bsdffile resolves relative to the scene file; a missing file
// fails at the parameter's location with the path.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "parser/parser.h"
#include "parser/scene_builder.h"
#include "support/fourier_bsdf_writer.h"
#include "support/render_scene.h"
#include "support/test_device.h"

namespace candela {
namespace {

namespace fs = std::filesystem;

constexpr double kRho = 0.6;

struct TempDir {
  fs::path path;
  explicit TempDir(const std::string& name)
      : path(fs::temp_directory_path() /
             ("candela_fourier_scene_" + std::to_string(::getpid()) + "_" + name)) {
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
};

std::string planeScene(const std::string& material, int spp) {
  std::string n = std::to_string(spp);
  return "LookAt 0 0 5  0 0 0  0 1 0\n"
         "Camera \"perspective\" \"float fov\" [30]\n"
         "Film \"image\" \"integer xresolution\" [8] \"integer yresolution\" [8]\n"
         "Sampler \"stratified\" \"integer xsamples\" [" +
         n + "] \"integer ysamples\" [" + n +
         "]\n"
         "SurfaceIntegrator \"path\"\nWorldBegin\n"
         "LightSource \"infinite\" \"rgb L\" [1 1 1]\n" +
         material +
         "\nShape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3]\n"
         "  \"point P\" [-1000 -1000 0  1000 -1000 0  1000 1000 0  -1000 1000 0]\n"
         "WorldEnd\n";
}

struct ImageMean {
  double mean = 0, standardError = 0;
};
ImageMean greenMean(const Film& film) {
  Bounds2i b = film.pixelBounds();
  std::vector<double> v;
  for (int y = b.pMin.y; y < b.pMax.y; ++y)
    for (int x = b.pMin.x; x < b.pMax.x; ++x) v.push_back(film.pixelValue(Point2i(x, y))[1]);
  ImageMean m;
  for (double x : v) m.mean += x;
  m.mean /= double(v.size());
  double ss = 0;
  for (double x : v) ss += (x - m.mean) * (x - m.mean);
  m.standardError = std::sqrt(ss / double(v.size() - 1) / double(v.size()));
  return m;
}

TEST(FourierMaterialScene, LambertianTableRendersLikeMatte) {
  TempDir dir("matte");
  fs::path file = dir.path / "lambert.bsdf";
  test::writeBytes(file.string(), test::fourierBsdfFileBytes(test::lambertianModel(kRho),
                                                             test::splitUniformNodes(10)));
  auto fourier = test::renderSceneText(
      planeScene("Material \"fourier\" \"string bsdffile\" \"" + file.string() + "\"", 8));
  auto matte = test::renderSceneText(planeScene("Material \"matte\" \"rgb Kd\" [0.6 0.6 0.6]", 8));
  ImageMean f = greenMean(fourier.film()), m = greenMean(matte.film());
  double combined = std::hypot(f.standardError, m.standardError);
  EXPECT_LT(std::abs(f.mean - m.mean), 4 * combined)
      << "fourier " << f.mean << " +- " << f.standardError << ", matte " << m.mean << " +- "
      << m.standardError;
  EXPECT_LT(std::abs(f.mean - kRho), 4 * f.standardError) << f.mean << " +- " << f.standardError;
  EXPECT_LT(std::abs(m.mean - kRho), 4 * m.standardError) << m.mean << " +- " << m.standardError;
  // The noise is small against the value: the comparison has resolution.
  EXPECT_LT(combined, 0.01);
}

TEST(FourierMaterialScene, BsdfFileIsRelativeToTheSceneFile) {
  TempDir dir("relative");
  fs::create_directories(dir.path / "bsdfs");
  test::writeBytes(
      (dir.path / "bsdfs" / "lambert.bsdf").string(),
      test::fourierBsdfFileBytes(test::lambertianModel(kRho), test::splitUniformNodes(10)));
  fs::path scene = dir.path / "scene.pbrt";
  {
    std::ofstream out(scene);
    out << planeScene("Material \"fourier\" \"string bsdffile\" \"bsdfs/lambert.bsdf\"", 1);
  }
  int built = 0;
  SceneBuilder builder(
      [&](SceneDescription&& desc) {
        RenderJob job = buildRenderJob(desc, BuildOptions{}, test::embreeDevice());
        ++built;
      },
      {});
  parseFile(scene.string(), builder);
  builder.endOfInput(FileLoc{scene.string(), 0, 0});
  EXPECT_EQ(built, 1);
}

TEST(FourierMaterialScene, MissingFileFailsWithThePathAtTheParameter) {
  fs::path missing = fs::temp_directory_path() / "candela_no_such_dir" / "missing.bsdf";
  std::string text =
      planeScene("Material \"fourier\" \"string bsdffile\" \"" + missing.string() + "\"", 1);
  try {
    test::buildSceneText(text);
    FAIL() << "no error";
  } catch (const SceneError& e) {
    std::string m = e.what();
    EXPECT_NE(m.find(missing.string()), std::string::npos) << m;
    EXPECT_NE(m.find("test.pbrt:8:"), std::string::npos) << m;
    EXPECT_NE(m.find("no such file"), std::string::npos) << m;
  }
  try {
    test::buildSceneText(planeScene("Material \"fourier\"", 1));
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("fourier needs \"string bsdffile\""), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace candela
