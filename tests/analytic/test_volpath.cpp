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
// The chromatic furnaces' (see expectBlocksAreTheSky).
constexpr int kChromaticSpp = 1024;
constexpr int kBlock = 4;

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
std::string furnaceScene(const std::string& medium, bool cameraInside, int spp = kSpp) {
  std::string camera = cameraInside ? "LookAt 0 0.1 -0.2  0 0 1  0 1 0\n"
                                      "MediumInterface \"\" \"fog\"\n"
                                    : "LookAt 0 0 -3  0 0 0  0 1 0\n";
  return camera +
         "Camera \"perspective\" \"float fov\" [45]\n"
         "Film \"image\" \"integer xresolution\" [" +
         std::to_string(kRes) + "] \"integer yresolution\" [" + std::to_string(kRes) +
         "]\n"
         "Sampler \"random\" \"integer pixelsamples\" [" +
         std::to_string(spp) +
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
// ratios over many scatterings has heavy tails, so a pixel's mean is far from normal: its rare
// large weights raise both the mean and the film's variance estimate, and a pixel that drew none
// is dark with a small variance. The per-pixel test above, at 256 spp, flagged a pixel for 15 and
// 16 of seeds 1-60 (grid / homogeneous) with the random sampler of the time, 19 and 10 with a
// one-hash stream: a family-wise level of about 25 %, not 1 %; at 1024 spp still 7 and 2 of 60.
// So these test blocks of 4 x 4 pixels (16 x 1024 paths each, whose means are close to normal)
// at 1024 spp, each channel of each block against the sky by its z from the film's variance
// estimates (the pixels are independent), two-sided at Šidák 0.01 over the blocks and channels.
// Measured over seeds 1-60 with both streams (240 renders): 1 false alarm (0.4 %; at Šidák 0.05,
// 0.1 and 0.2: 11, 22 and 42 of 240, the nominal 12, 24 and 48). It finds a bias: with an
// albedo of 0.98 instead of 1 it failed all 49 renders tried (both streams), with 0.995 19 of 20
// (seeds 1-10, both scenes), where the per-pixel test failed 5 of those 20.
void expectBlocksAreTheSky(const Film& film) {
  constexpr int blocks = kRes / kBlock;
  const int checks = blocks * blocks * 3;
  for (int by = 0; by < blocks; ++by)
    for (int bx = 0; bx < blocks; ++bx)
      for (int c = 0; c < 3; ++c) {
        double sum = 0, variance = 0;
        for (int y = by * kBlock; y < (by + 1) * kBlock; ++y)
          for (int x = bx * kBlock; x < (bx + 1) * kBlock; ++x) {
            double v = film.pixelValue(Point2i(x, y))[c];
            ASSERT_TRUE(std::isfinite(v));
            sum += v;
            variance += film.pixelVariance(Point2i(x, y))[c];
          }
        const double n = kBlock * kBlock, mean = sum / n;
        if (variance == 0) {
          EXPECT_NEAR(mean, 1, 1e-5) << "block " << bx << "," << by;
          continue;
        }
        double z = (mean - 1) / (std::sqrt(variance) / n);
        EXPECT_GT(stats::normalTwoSidedTail(z), stats::sidak(0.01, checks))
            << "block " << bx << "," << by << " channel " << c << ": " << mean << " (z " << z
            << ")";
      }
}

// Besides the blocks, the mean over the pixels that see the medium against the standard error
// from their spread, two-sided at 0.01 / 3 per channel (over the same 240 renders: 1 false alarm;
// at 0.05, 0.1, 0.2: 8, 24, 44). (At 4096 spp the homogeneous image's channel means are 1.0003,
// 1.0006 and 0.9999, its pixels within [0.94, 1.05].)
void expectImageMeanIsTheSky(const Film& film) {
  for (int c = 0; c < 3; ++c) {
    double sum = 0, sumSq = 0;
    int n = 0;
    for (int y = 0; y < kRes; ++y)
      for (int x = 0; x < kRes; ++x) {
        if (film.pixelVariance(Point2i(x, y))[c] == 0) continue;
        double v = film.pixelValue(Point2i(x, y))[c];
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

void expectChromaticFurnaceIsTheSky(const std::string& medium, bool cameraInside) {
  test::TestRenderOptions o;
  o.build.seed = 9;
  auto r = test::renderSceneText(furnaceScene(medium, cameraInside, kChromaticSpp), o);
  expectImageMeanIsTheSky(r.film());
  expectBlocksAreTheSky(r.film());
}

TEST(VolPathFurnace, ChromaticHomogeneousSeenFromOutside) {
  expectChromaticFurnaceIsTheSky(
      "\"homogeneous\" \"rgb sigma_a\" [0 0 0] \"rgb sigma_s\" [1 2 4] \"float g\" [0.5]", false);
}

TEST(VolPathFurnace, ChromaticGridAroundTheCamera) {
  expectChromaticFurnaceIsTheSky(
      gridDensity() + " \"rgb sigma_a\" [0 0 0] \"rgb sigma_s\" [3 1.5 2]", true);
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
  test::PixelPasses renderer(job);
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
// region (both with closed-form transmittance, so "single"'s marching is unbiased). The light is
// above the fog: inside it, volpath's in-scattering estimate (I / r^2 at a distance-sampled point)
// has infinite variance near the light (r^-4 is not integrable over a volume around a point), and
// the region holding the light had replicate means of skewness 14, the largest 16 times the mean:
// the exponential region failed for 4 of 44 disjoint sets of 24 seeds with the random sampler of
// the time and 3 of 45 with a one-hash stream, though pooled over all those seeds no region
// differed (largest |z| 1.9). With the light above the fog every region's skewness is below 0.2,
// and with Student's tails (region_agreement.h) it fails 1 of 120 seed sets (both streams; at
// family-wise 0.05, 0.1 and 0.2: 8, 13 and 25 of 120). It finds a bias: volpath with sigma_s 3 %
// too large (regions 1-2 % off) fails 19 of 20 seed sets.
std::string foggyFloor(const std::string& integrator, const std::string& region) {
  return "LookAt 0 1.2 -4  0 0.6 0  0 1 0\n"
         "Camera \"perspective\" \"float fov\" [45]\n"
         "Film \"image\" \"integer xresolution\" [16] \"integer yresolution\" [16]\n"
         "Sampler \"random\" \"integer pixelsamples\" [16]\n" +
         integrator +
         "\nWorldBegin\n"
         "LightSource \"point\" \"point from\" [0.3 2.8 0.2] \"rgb I\" [10 10 10]\n"
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
