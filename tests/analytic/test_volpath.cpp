// Integrator "volpath" (pbrt-v3's media): the volumetric furnace — a bounded medium that scatters
// without absorbing (albedo 1 in every channel), inside a pure interface (a sphere with Material
// "none") under a uniform sky, seen from outside and from inside: every pixel equals the sky —
// and, without media, agreement with "path".
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "media/grid_density_medium.h"
#include "support/region_agreement.h"
#include "support/render_scene.h"
#include "support/tail_probabilities.h"

namespace candela {
namespace {

constexpr int kRes = 16;
constexpr int kSpp = 256;

// A smooth 8^3 density over [-1, 1]^3 (a bump on a floor of 0.2), written into the scene.
std::string gridDensity() {
  std::string d;
  const int n = 8;
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        double px = (x + 0.5) / n * 2 - 1, py = (y + 0.5) / n * 2 - 1, pz = (z + 0.5) / n * 2 - 1;
        d += std::to_string(0.2 + std::max(0.0, 1 - 0.5 * (px * px + py * py + pz * pz))) + " ";
      }
  return "\"heterogeneous\" \"integer nx\" [8] \"integer ny\" [8] \"integer nz\" [8] "
         "\"point p0\" [-1 -1 -1] \"point p1\" [1 1 1] \"float density\" [" +
         d + "]";
}

// medium: the MakeNamedMedium's type and coefficients; the sky has radiance 1.
std::string furnaceScene(const std::string& medium, bool cameraInside) {
  std::string camera = cameraInside ? "LookAt 0 0.1 -0.2  0 0 1  0 1 0\n"
                                      "MediumInterface \"\" \"fog\"\n"
                                    : "LookAt 0 0 -3  0 0 0  0 1 0\n";
  return camera +
         "Camera \"perspective\" \"float fov\" [45]\n"
         "Film \"image\" \"integer xresolution\" [" +
         std::to_string(kRes) + "] \"integer yresolution\" [" + std::to_string(kRes) +
         "]\n"
         "Sampler \"random\" \"integer pixelsamples\" [" +
         std::to_string(kSpp) +
         "]\n"
         "Integrator \"volpath\" \"integer maxdepth\" [100000]\n"
         "WorldBegin\n"
         // In the world block: before WorldBegin the CTM is the camera's (pbrt-v3 keeps a
         // medium there in camera space).
         "MakeNamedMedium \"fog\" \"string type\" " +
         medium +
         "\n"
         "LightSource \"infinite\" \"rgb L\" [1 1 1]\n"
         "AttributeBegin\n"
         "MediumInterface \"fog\" \"\"\n"
         "Material \"none\"\n"
         "Shape \"sphere\" \"float radius\" [1]\n"
         "AttributeEnd\n"
         "WorldEnd\n";
}

// Every pixel's channel against the sky, by its z from the film's own variance estimate;
// two-sided at Šidák 0.01 over all pixels and channels. 256 paths per pixel, each path's
// estimate of bounded variance, so the normal approximation of the pixel mean holds. Pixels
// whose camera rays miss the sphere see the sky exactly.
void expectFilmIsTheSky(const Film& film, bool expectMedium) {
  const int checks = kRes * kRes * 3;
  int inMedium = 0;
  for (int y = 0; y < kRes; ++y)
    for (int x = 0; x < kRes; ++x) {
      Spectrum v = film.pixelValue(Point2i(x, y)), var = film.pixelVariance(Point2i(x, y));
      if (var.maxComponent() > 0) ++inMedium;
      for (int c = 0; c < 3; ++c) {
        ASSERT_TRUE(std::isfinite(v[c]));
        if (var[c] == 0) {
          EXPECT_NEAR(v[c], 1, 1e-5) << "pixel " << x << "," << y;
          continue;
        }
        double z = (v[c] - 1) / std::sqrt(double(var[c]));
        EXPECT_GT(stats::normalTwoSidedTail(z), stats::sidak(0.01, checks))
            << "pixel " << x << "," << y << " channel " << c << ": " << v[c] << " (z " << z << ")";
      }
    }
  // The medium is really there: its pixels are noisy estimates, not the sky passed through.
  if (expectMedium) {
    EXPECT_GT(inMedium, kRes * kRes / 4);
  }
}

void expectEveryPixelIsTheSky(const std::string& scene, bool expectMedium) {
  test::TestRenderOptions o;
  o.build.seed = 5;
  auto r = test::renderSceneText(scene, o);
  expectFilmIsTheSky(r.film(), expectMedium);
}

TEST(VolPathFurnace, HomogeneousSeenFromOutside) {
  expectEveryPixelIsTheSky(
      furnaceScene("\"homogeneous\" \"rgb sigma_a\" [0 0 0] \"rgb sigma_s\" [2 2 2] "
                   "\"float g\" [0.5]",
                   false),
      true);
}

// Chromatic σs: each channel scatters at its own rate. A flight samples one channel's distance
// (chosen by the path's throughput) and weights the others by the ratio; the product of those
// ratios over many scatterings can have heavy tails, which would make the film's per-pixel
// variance estimate unreliable, so besides the per-pixel check these also test the mean over the
// pixels that see the medium against the standard error from their spread, two-sided at
// 0.01 / 3 per channel. (At 4096 spp the homogeneous image's channel means are 1.0003, 1.0006 and
// 0.9999, its pixels within [0.94, 1.05].)
void expectImageMeanIsTheSky(const std::string& scene) {
  test::TestRenderOptions o;
  o.build.seed = 9;
  auto r = test::renderSceneText(scene, o);
  for (int c = 0; c < 3; ++c) {
    double sum = 0, sumSq = 0;
    int n = 0;
    for (int y = 0; y < kRes; ++y)
      for (int x = 0; x < kRes; ++x) {
        if (r.film().pixelVariance(Point2i(x, y))[c] == 0) continue;
        double v = r.film().pixelValue(Point2i(x, y))[c];
        sum += v;
        sumSq += v * v;
        ++n;
      }
    ASSERT_GT(n, kRes * kRes / 4);
    double mean = sum / n, se = std::sqrt((sumSq / n - mean * mean) / (n - 1));
    double z = (mean - 1) / se;
    EXPECT_GT(stats::normalTwoSidedTail(z), 0.01 / 3)
        << "channel " << c << ": mean " << mean << " (z " << z << ")";
  }
}

TEST(VolPathFurnace, ChromaticHomogeneousSeenFromOutside) {
  std::string scene = furnaceScene(
      "\"homogeneous\" \"rgb sigma_a\" [0 0 0] \"rgb sigma_s\" [1 2 4] \"float g\" [0.5]", false);
  expectImageMeanIsTheSky(scene);
  expectEveryPixelIsTheSky(scene, true);
}

TEST(VolPathFurnace, ChromaticGridAroundTheCamera) {
  std::string scene =
      furnaceScene(gridDensity() + " \"rgb sigma_a\" [0 0 0] \"rgb sigma_s\" [3 1.5 2]", true);
  expectImageMeanIsTheSky(scene);
  expectEveryPixelIsTheSky(scene, true);
}

TEST(VolPathFurnace, HomogeneousAroundTheCamera) {
  expectEveryPixelIsTheSky(
      furnaceScene("\"homogeneous\" \"rgb sigma_a\" [0 0 0] \"rgb sigma_s\" [2 2 2] "
                   "\"float g\" [-0.3]",
                   true),
      true);
}

TEST(VolPathFurnace, GridSeenFromOutside) {
  expectEveryPixelIsTheSky(
      furnaceScene(gridDensity() + " \"rgb sigma_a\" [0 0 0] \"rgb sigma_s\" [3 3 3]", false),
      true);
}

TEST(VolPathFurnace, GridAroundTheCamera) {
  expectEveryPixelIsTheSky(
      furnaceScene(gridDensity() + " \"rgb sigma_a\" [0 0 0] \"rgb sigma_s\" [2 2 2] "
                                   "\"float g\" [0.4]",
                   true),
      true);
}

// pbrt-v2 Volume regions reach volpath as Scene::volume(), the medium that fills the scene: a
// bounded non-absorbing grid set as that volume (no interface anywhere) is a furnace too.
TEST(VolPathFurnace, SceneVolumeFillsTheScene) {
  // No shapes and no named media: the sky and the volume alone.
  std::string scene = furnaceScene("\"homogeneous\"", false);
  scene = scene.substr(0, scene.find("MakeNamedMedium")) + "LightSource \"infinite\"\nWorldEnd\n";
  BuildOptions options;
  options.seed = 5;
  auto built = test::buildSceneText(scene, options);
  RenderJob& job = built.job();
  std::vector<Float> density = {0.5f, 1, 2, 1, 1, 0.5f, 2, 1};
  GridDensityMedium volume(Spectrum(0), Spectrum(2), 0.2f, 2, 2, 2, density, Point3f(-1, -1, -1),
                           Point3f(1, 1, 1), rotate(30, Vector3f(1, 1, 0)));
  Scene withVolume(job.aggregate.get(), job.scene->lights(), &volume);
  // The sky's shadow rays must end beyond the volume: the lights see the scene's new bounds.
  for (const auto& light : job.lights) light->preprocess(withVolume.worldBound());
  SamplerRenderer renderer(*job.camera, *job.sampler, *job.integrator);
  renderer.render(withVolume, *job.film, RenderOptions{0, 16, true});
  expectFilmIsTheSky(*job.film, true);
}

// The furnace fails when something absorbs: the check can fail.
TEST(VolPathFurnace, AnAbsorbingMediumIsDarkerThanTheSky) {
  test::TestRenderOptions o;
  auto r = test::renderSceneText(
      furnaceScene("\"homogeneous\" \"rgb sigma_a\" [0.5 0.5 0.5] \"rgb sigma_s\" [2 2 2]", false),
      o);
  EXPECT_LT(r.film().pixelValue(Point2i(kRes / 2, kRes / 2)).y(), 0.8f);
}

// Without media, volpath is path tracing: the Cornell box's 16 regions agree (see
// region_agreement.h for the test and its significance).
TEST(VolPath, AgreesWithPathWithoutMedia) {
  test::expectRegionsAgree(
      test::renderRegionReplicates(
          test::cornellBoxText(16, "Integrator \"volpath\" \"integer maxdepth\" [5]"), 32, 8),
      "volpath",
      test::renderRegionReplicates(
          test::cornellBoxText(16, "SurfaceIntegrator \"path\" \"integer maxdepth\" [5]"), 32, 8),
      "path");
}

// A pbrt-v2 Volume statement with volpath: volpath carries the light through the region itself,
// so the scene's VolumeIntegrator must not add its own on top (with "single" the furnace would
// come out brighter than the sky). The integrator is ignored with a warning.
TEST(VolPathFurnace, VolumeStatementWithAVolumeIntegratorIsStillTheSky) {
  std::string scene = furnaceScene("\"homogeneous\"", false);
  scene = scene.substr(0, scene.find("MakeNamedMedium")) +
          "Volume \"homogeneous\" \"rgb sigma_s\" [2 1 0.5] \"float g\" [0.4]\n"
          "    \"point p0\" [-1 -1 -1] \"point p1\" [1 1 1]\n"
          "LightSource \"infinite\"\nWorldEnd\n";
  scene.insert(scene.find("WorldBegin"), "VolumeIntegrator \"single\" \"float stepsize\" [0.05]\n");
  test::TestRenderOptions o;
  o.build.seed = 5;
  std::vector<std::string> warnings;
  o.build.warn = [&](const FileLoc&, const std::string& m) { warnings.push_back(m); };
  auto r = test::renderSceneText(scene, o);
  expectFilmIsTheSky(r.film(), true);
  bool warned = false;
  for (const auto& w : warnings) warned |= w.find("VolumeIntegrator 'single' is ignored") == 0;
  EXPECT_TRUE(warned);
}

// Fog over a floor, lit by a point light, in pbrt-v2's dialect: `directlighting` with
// VolumeIntegrator "single" counts light that scattered once in the fog and light that reflected
// once off the floor, each attenuated along the way; volpath limited to one scattering event
// (maxdepth 1: medium or surface) estimates the same image. Compared region by region (see
// region_agreement.h for the test and its significance), for a homogeneous and an exponential
// region (both with closed-form transmittance, so "single"'s marching is unbiased).
std::string foggyFloor(const std::string& integrator, const std::string& region) {
  return "LookAt 0 1.2 -4  0 0.6 0  0 1 0\n"
         "Camera \"perspective\" \"float fov\" [45]\n"
         "Film \"image\" \"integer xresolution\" [16] \"integer yresolution\" [16]\n"
         "Sampler \"random\" \"integer pixelsamples\" [16]\n" +
         integrator +
         "\nWorldBegin\n"
         "LightSource \"point\" \"point from\" [0.3 1.5 0.2] \"rgb I\" [3 3 3]\n"
         "Volume " +
         region +
         " \"rgb sigma_a\" [0.1 0.2 0.3] \"rgb sigma_s\" [0.6 0.5 0.4] \"float g\" [0.3]\n"
         "    \"point p0\" [-2 0 -2] \"point p1\" [2 2.5 2]\n"
         "Material \"matte\" \"rgb Kd\" [0.6 0.5 0.4]\n"
         "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3]\n"
         "  \"point P\" [-3 0 -3  3 0 -3  3 0 3  -3 0 3]\n"
         "WorldEnd\n";
}

class VolPathOneScatteringEvent : public testing::TestWithParam<const char*> {};

TEST_P(VolPathOneScatteringEvent, AgreesWithTheSingleScatteringIntegrator) {
  const std::string region = GetParam();
  test::expectRegionsAgree(
      test::renderRegionReplicates(
          foggyFloor("Integrator \"volpath\" \"integer maxdepth\" [1]", region), 24, 64),
      "volpath",
      test::renderRegionReplicates(
          foggyFloor("SurfaceIntegrator \"directlighting\"\n"
                     "VolumeIntegrator \"single\" \"float stepsize\" [0.1]",
                     region),
          24, 64),
      "single");
}

// The check can fail: a second scattering event adds light that "single" does not count.
TEST(VolPathOneScatteringEvent, MoreEventsAreBrighterThanSingleScattering) {
  const std::string region = "\"homogeneous\"";
  auto mean = [](const test::RegionReplicates& r) {
    double s = 0;
    for (double v : r.sum) s += v;
    return s;
  };
  double one = mean(test::renderRegionReplicates(
      foggyFloor("Integrator \"volpath\" \"integer maxdepth\" [1]", region), 4, 16));
  double many = mean(test::renderRegionReplicates(
      foggyFloor("Integrator \"volpath\" \"integer maxdepth\" [20]", region), 4, 16));
  EXPECT_GT(many, 1.05 * one);
}

INSTANTIATE_TEST_SUITE_P(Regions, VolPathOneScatteringEvent,
                         testing::Values("\"homogeneous\"", "\"exponential\" \"float b\" [0.8]"));

}  // namespace
}  // namespace candela
