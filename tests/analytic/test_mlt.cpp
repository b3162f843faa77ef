// Metropolis light transport (pbrt-v3 "mlt", pbrt-v2 Renderer "metropolis") against closed forms.
// A Metropolis image is not a per-pixel average of independent samples, so each test renders
// independent replicates (seeds 1..R) and tests, for every pixel, the replicates' mean against
// the closed form with the replicates' own standard error: z = (mean - expected) / (sd / √R),
// two-sided, per-pixel significance Šidák 0.01 over the pixels (normal approximation; with R = 32
// the Student tails make the family-wise level about 0.02). Fixed seeds.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "support/render_scene.h"
#include "support/tail_probabilities.h"

namespace candela {
namespace {

std::string scene(const std::string& transport, const std::string& camera, const std::string& world,
                  int res) {
  return camera + "\nFilm \"image\" \"integer xresolution\" [" + std::to_string(res) +
         "] \"integer yresolution\" [" + std::to_string(res) + "]\n" + transport +
         "\nWorldBegin\n" + world + "\nWorldEnd\n";
}

// Small runs: these scenes are simple enough that a few chains mix.
std::string mlt(int maxDepth, int mutations) {
  return "Integrator \"mlt\" \"integer maxdepth\" [" + std::to_string(maxDepth) +
         "] \"integer bootstrapsamples\" [2000] \"integer chains\" [32] "
         "\"integer mutationsperpixel\" [" +
         std::to_string(mutations) + "]";
}

std::string metropolis(int maxDepth, int mutations, const std::string& extra) {
  return "Renderer \"metropolis\" \"integer maxdepth\" [" + std::to_string(maxDepth) +
         "] \"integer bootstrapsamples\" [1000] \"integer samplesperpixel\" [" +
         std::to_string(mutations) + "] " + extra;
}

// The per-pixel test over R replicates (see the top of the file), and the same z-test for the
// image's mean over the pixels (significance 0.01), which sees a small bias the per-pixel test is
// too weak to.
void expectPixelsMatch(const std::string& text, int res, int replicates,
                       const std::function<double(int, int)>& expected) {
  std::vector<double> sum(size_t(res * res)), sumSq(size_t(res * res));
  double imageSum = 0, imageSumSq = 0, imageExpected = 0;
  for (int rep = 0; rep < replicates; ++rep) {
    test::TestRenderOptions o;
    o.build.seed = uint64_t(rep + 1);
    auto r = test::renderSceneText(text, o);
    for (int y = 0; y < res; ++y)
      for (int x = 0; x < res; ++x) {
        double v = r.film().pixelValue(Point2i(x, y)).y();
        sum[size_t(y * res + x)] += v;
        sumSq[size_t(y * res + x)] += v * v;
      }
    double mean = 0;
    for (int i = 0; i < res * res; ++i) mean += r.film().pixelValue(Point2i(i % res, i / res)).y();
    mean /= res * res;
    imageSum += mean;
    imageSumSq += mean * mean;
  }
  const double n = replicates;
  double worst = 1;
  for (int y = 0; y < res; ++y)
    for (int x = 0; x < res; ++x) {
      size_t i = size_t(y * res + x);
      double m = sum[i] / n, var = std::max(0.0, (sumSq[i] - n * m * m) / (n - 1));
      double e = expected(x, y);
      imageExpected += e / (res * res);
      double z = (m - e) / std::max(std::sqrt(var / n), 1e-6 * e);
      double p = stats::normalTwoSidedTail(z);
      worst = std::min(worst, p);
      EXPECT_GT(p, stats::sidak(0.01, res * res))
          << "pixel " << x << "," << y << ": mean " << m << ", expected " << e << ", z " << z;
    }
  ::testing::Test::RecordProperty("smallest_p", std::to_string(worst));
  // A floor on the standard error of 1e-6 relative: float rounding, when every path has the
  // same contribution (unidirectional paths in the furnace) and the replicates agree exactly.
  double m = imageSum / n, var = std::max(0.0, (imageSumSq - n * m * m) / (n - 1));
  double z = (m - imageExpected) / std::max(std::sqrt(var / n), 1e-6 * imageExpected);
  EXPECT_GT(stats::normalTwoSidedTail(z), 0.01)
      << "image mean " << m << ", expected " << imageExpected << ", z " << z;
}

// A closed sphere of albedo 0.5 emitting Le = 0.5 everywhere, seen from inside: with at most d
// reflections L = Le Σ_{i=0..d} ρ^i = 1 - 0.5^(d+1) at every pixel.
const char* kInsideSphere = "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"perspective\" \"float fov\" [60]";
const char* kFurnace =
    "Material \"matte\" \"rgb Kd\" [0.5 0.5 0.5]\n"
    "AreaLightSource \"diffuse\" \"rgb L\" [0.5 0.5 0.5]\n"
    "ReverseOrientation\n"
    "Shape \"sphere\" \"float radius\" [1]\n";

TEST(MltFurnace, ClosedEmittingSphere) {
  const double expected = 1 - std::pow(0.5, 7);
  expectPixelsMatch(scene(mlt(6, 32), kInsideSphere, kFurnace, 8), 8, 32,
                    [&](int, int) { return expected; });
}

TEST(MetropolisFurnace, ClosedEmittingSphereEveryVariant) {
  const double expected = 1 - std::pow(0.5, 5);
  for (const char* variant :
       {"", "\"bool bidirectional\" \"false\"", "\"bool dodirectseparately\" \"false\"",
        "\"bool dodirectseparately\" \"false\" \"bool bidirectional\" \"false\""}) {
    SCOPED_TRACE(variant);
    expectPixelsMatch(scene(metropolis(4, 32, variant), kInsideSphere, kFurnace, 8), 8, 32,
                      [&](int, int) { return expected; });
  }
}

// Looking straight down from height 1 at a disk of albedo ρ on z = 0 (fov 40°): the mean over
// pixel (x, y) of g(r), r the distance from the axis where the ray meets the floor, by an 8 x 8
// midpoint rule (g is smooth: error < 1e-4).
double pixelMean(int x, int y, int res, const std::function<double(double)>& g) {
  const double tanHalf = 0.36397023426620234;
  double sum = 0;
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) {
      double sx = -1 + 2 * (x + (i + 0.5) / 8) / res, sy = 1 - 2 * (y + (j + 0.5) / 8) / res;
      sum += g(tanHalf * std::sqrt(sx * sx + sy * sy));
    }
  return sum / 64;
}

const char* kLookDown = "LookAt 0 0 1  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" [40]";

// A diffuse disk under a uniform sky: L = ρ/π · π L_sky = ρ L_sky = 0.8 at every pixel.
TEST(MltAnalytic, DiffuseDiskUnderUniformSky) {
  const char* world =
      "LightSource \"infinite\" \"rgb L\" [2 2 2]\n"
      "Material \"matte\" \"rgb Kd\" [0.4 0.4 0.4]\n"
      "Shape \"disk\" \"float radius\" [4]\n";
  expectPixelsMatch(scene(mlt(3, 32), kLookDown, world, 8), 8, 32, [](int, int) { return 0.8; });
}

// A point light of intensity I at height hL on the axis of a diffuse disk: E(r) = I hL /
// (hL² + r²)^{3/2} and L = ρ/π E. Also by pbrt-v2's unidirectional chains.
TEST(MltAnalytic, PointLightOverDiffuseDisk) {
  const char* world =
      "LightSource \"point\" \"point from\" [0 0 0.6] \"rgb I\" [3 3 3]\n"
      "Material \"matte\" \"rgb Kd\" [0.5 0.5 0.5]\n"
      "Shape \"disk\" \"float radius\" [4]\n";
  auto L = [](double r) { return 0.5 / M_PI * 3 * 0.6 / std::pow(0.36 + r * r, 1.5); };
  auto expected = [&](int x, int y) { return pixelMean(x, y, 8, L); };
  expectPixelsMatch(scene(mlt(3, 32), kLookDown, world, 8), 8, 32, expected);
  expectPixelsMatch(
      scene(metropolis(3, 32,
                       "\"bool bidirectional\" \"false\" \"bool dodirectseparately\" \"false\""),
            kLookDown, world, 8),
      8, 32, expected);
}

// A mirror (Kr 0.9) under a uniform sky: every pixel sees the sky through one specular bounce,
// L = 0.9 L_sky = 1.8. With direct lighting rendered separately this is the directlighting
// integrator's (its specular recursion) at maxdepth 3, but the chains' at maxdepth 1, where that
// recursion stops before the bounce: each variant must count it exactly once.
TEST(MetropolisAnalytic, MirrorUnderUniformSky) {
  const char* world =
      "LightSource \"infinite\" \"rgb L\" [2 2 2]\n"
      "Material \"mirror\"\n"
      "Shape \"disk\" \"float radius\" [4]\n";
  for (int maxDepth : {1, 3}) {
    for (const char* variant :
         {"", "\"bool bidirectional\" \"false\"", "\"bool dodirectseparately\" \"false\""}) {
      SCOPED_TRACE(std::string(variant) + " maxdepth " + std::to_string(maxDepth));
      expectPixelsMatch(scene(metropolis(maxDepth, 64, variant), kLookDown, world, 4), 4, 32,
                        [](int, int) { return 1.8; });
    }
    expectPixelsMatch(scene(mlt(maxDepth, 64), kLookDown, world, 4), 4, 32,
                      [](int, int) { return 1.8; });
  }
}

}  // namespace
}  // namespace candela
