// An exact furnace at every scale (issue 15): tests/robustness/scenes/furnace-sphere.pbrt, the
// camera at the centre of a closed diffuse sphere of albedo rho emitting Le inward. From a point
// of a sphere, cos cos' / r^2 = 1 / (4 R^2) for every other point, so the light's area sampling
// has the density cos / pi of the BSDF's cosine sampling: both of the power heuristic's
// estimates are rho Le, and every path of maxdepth d returns Le (1 + rho + ... + rho^d) with no
// variance (emission seen at the first hit, then next-event estimation at each of d vertices).
// "path" runs Russian roulette after its third bounce, so it runs at maxdepth 3; "volpath" with
// rrthreshold 0 has none and runs at maxdepth 12 and (Kd 0.999) at 1000.
//
// What is left is float rounding of the points, relative spacing eps = 2^-24 (|offset| + R) / R
// at the hit points: a float point lies off the sphere by up to its rounding h, and along a
// chord that leaves it at a grazing angle theta the light's area density and the BSDF's cosine
// density then differ by about h / (2 R cos^2 theta); the power heuristic turns unequal pdfs into
// a deficit (its sum is largest when they agree). So the deviations are a few hundredths of an
// eps in almost every pixel and, rarely, one pixel tens or hundreds of eps low, where one of its
// samples went out within a few thousandths of the tangent plane (P(cos theta < c) = c^2 for
// cosine sampling): measured over seeds 1-40 at 1e3 and 1e5 from the origin, 10 of 40 renders
// have 1 to 4 such pixels beyond 64 eps, up to 513 eps, and so does 1 render in 40 at the
// origin; the 90th-percentile pixel is within 0.1 eps. A per-pixel bound is therefore met only
// by a seed's luck, and this test asserts what rounding does imply instead: the 90th-percentile
// pixel within 1 eps, and no more than 8 of the 256 pixels beyond
// 64 eps (path) and 512 eps (volpath). A lost shadow ray or a self-hit is not a rare grazing
// event: it recurs at every vertex where its cause does and moves its pixel by at least
// 0.5^3 / 2 / 16 / 1.875 = 2e-3 (path) each time, far more pixels than 8.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "scene_files.h"
#include "support/render_scene.h"
#include "support/robustness_figures.h"

namespace candela {
namespace {

struct Furnace {
  double radius = 1, offset = 0;  // the sphere's radius and its centre's x = y = z
  std::string integrator;         // replaces the path statement when not empty
  int resolution = 16, spp = 16;
  double albedo = 0.5;
};

// The scene file with the camera and the sphere moved to (offset, offset, offset) and the sphere
// scaled to the radius.
std::string furnaceText(const Furnace& f) {
  std::string s = test::robustnessScene("furnace-sphere.pbrt");
  std::ostringstream look, move, res, spp, kd;
  look.precision(17);
  move.precision(17);
  look << "LookAt " << f.offset << " " << f.offset << " " << f.offset << "  " << f.offset << " "
       << f.offset << " " << f.offset + f.radius << "  0 1 0";
  move << "WorldBegin\nTranslate " << f.offset << " " << f.offset << " " << f.offset << "\nScale "
       << f.radius << " " << f.radius << " " << f.radius << "\n";
  res << "\"integer xresolution\" [" << f.resolution << "] \"integer yresolution\" ["
      << f.resolution << "]";
  spp << "\"integer pixelsamples\" [" << f.spp << "]";
  kd << "\"rgb Kd\" [" << f.albedo << " " << f.albedo << " " << f.albedo << "]";
  test::replaceOnce(&s, "LookAt 0 0 0  0 0 1  0 1 0", look.str());
  test::replaceOnce(&s, "WorldBegin\n", move.str());
  test::replaceOnce(&s, "\"integer xresolution\" [16] \"integer yresolution\" [16]", res.str());
  test::replaceOnce(&s, "\"integer pixelsamples\" [16]", spp.str());
  test::replaceOnce(&s, "\"rgb Kd\" [0.5 0.5 0.5]", kd.str());
  if (!f.integrator.empty())
    test::replaceOnce(&s, "SurfaceIntegrator \"path\" \"integer maxdepth\" [3]", f.integrator);
  return s;
}

// Le (1 + rho + ... + rho^depth) with Le = 1.
double furnaceValue(double albedo, int depth) {
  return (1 - std::pow(albedo, depth + 1)) / (1 - albedo);
}

// Every pixel's largest relative deviation of a colour channel from expected, sorted; infinity
// for a pixel that is not finite.
std::vector<double> sortedDeviations(const Film& film, double expected) {
  ImageBuffer image = film.image();
  std::vector<double> deviations;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      double worst = 0;
      for (int c = 0; c < 3; ++c) {
        float v = image.at(x, y, c);
        worst = std::isfinite(v) ? std::max(worst, std::abs(v / expected - 1)) : INFINITY;
      }
      deviations.push_back(worst);
    }
  std::sort(deviations.begin(), deviations.end());
  return deviations;
}

double worstDeviation(const Film& film, double expected) {
  return sortedDeviations(film, expected).back();
}

// What the exact furnace asserts of a render (see the top): the bulk within bulkEps, at most
// kMaxGrazingPixels pixels beyond outlierEps.
constexpr int kMaxGrazingPixels = 8;
struct RoundingFigures {
  double percentile90 = 0;  // eps
  int outliers = 0;         // pixels beyond the outlier bound
  double worst = 0;         // eps
};

RoundingFigures roundingFigures(const Film& film, double expected, double eps, double outlierEps) {
  std::vector<double> d = sortedDeviations(film, expected);
  RoundingFigures r;
  r.percentile90 = d[d.size() * 9 / 10] / eps;
  r.outliers =
      int(std::count_if(d.begin(), d.end(), [&](double x) { return x > outlierEps * eps; }));
  r.worst = d.back() / eps;
  return r;
}

double floatSpacing(const Furnace& f) {
  return 0x1p-24 * (std::abs(f.offset) + f.radius) / f.radius;
}

std::string describe(const Furnace& f) {
  char s[64];
  std::snprintf(s, sizeof s, "radius %g at %g", f.radius, f.offset);
  return s;
}

Furnace placed(double radius, double offset) {
  Furnace f;
  f.radius = radius;
  f.offset = offset;
  return f;
}

const Furnace kPlacements[] = {placed(1e-6, 0), placed(1e-3, 0), placed(1, 0),    placed(1e3, 0),
                               placed(1e6, 0),  placed(10, 1e3), placed(1e3, 1e5)};

TEST(StiffFurnace, EveryPixelIsExactToRoundingFromTenToTheMinusSixToTheSixAndAt1e5) {
  RoundingFigures path, volpath;  // the worst of each figure over the renders
  auto keepWorst = [](RoundingFigures* worst, const RoundingFigures& r) {
    worst->percentile90 = std::max(worst->percentile90, r.percentile90);
    worst->outliers = std::max(worst->outliers, r.outliers);
    worst->worst = std::max(worst->worst, r.worst);
  };
  for (Furnace f : kPlacements) {
    double eps = floatSpacing(f);
    for (const char* accel : {"embree", "bvh", "kdtree", "grid"}) {
      test::TestRenderOptions options;
      options.build.accelerator = accel;
      RoundingFigures r = roundingFigures(test::renderSceneText(furnaceText(f), options).film(),
                                          furnaceValue(f.albedo, 3), eps, 64);
      EXPECT_LE(r.percentile90, 1) << describe(f) << ", " << accel << ", path";
      EXPECT_LE(r.outliers, kMaxGrazingPixels) << describe(f) << ", " << accel << ", path";
      keepWorst(&path, r);
    }
    f.integrator = "Integrator \"volpath\" \"integer maxdepth\" [12] \"float rrthreshold\" [0]";
    RoundingFigures r = roundingFigures(test::renderSceneText(furnaceText(f)).film(),
                                        furnaceValue(f.albedo, 12), eps, 512);
    EXPECT_LE(r.percentile90, 1) << describe(f) << ", volpath";
    EXPECT_LE(r.outliers, kMaxGrazingPixels) << describe(f) << ", volpath";
    keepWorst(&volpath, r);
  }
  test::recordFigure(
      "furnace sphere radius 1e-6..1e6, offsets 1e3 and 1e5, against Le (1 - rho^(d+1)) / "
      "(1 - rho), eps = float spacing at the hit points: 90th-percentile pixel within 1 eps "
      "(path, maxdepth 3; volpath, maxdepth 12), at most 8 of 256 pixels (rare grazing "
      "samples) beyond 64 / 512 eps",
      "90th percentile %.2f / %.1f eps; pixels beyond: at most %d / %d; worst pixel %.0f / %.0f "
      "eps (path, 4 accelerators / volpath)",
      path.percentile90, volpath.percentile90, path.outliers, volpath.outliers, path.worst,
      volpath.worst);
}

// Kd 0.999 to maxdepth 1000 (issue 15): (1 - 0.999^1001) / 0.001 = 632.67, through 1000
// products of throughput that each round by a few eps: held to 4096 eps (2.4e-4 at the origin,
// 2.5e-2 at 100 radii from it); measured 1.3e-5 and 8.3e-5.
TEST(StiffFurnace, AThousandBouncesOfAlbedo0999AreExactToRounding) {
  double worst = 0;
  for (Furnace f : {placed(1, 0), placed(10, 1e3)}) {
    f.albedo = 0.999;
    f.resolution = 8;
    f.spp = 4;
    f.integrator = "Integrator \"volpath\" \"integer maxdepth\" [1000] \"float rrthreshold\" [0]";
    double deviation =
        worstDeviation(test::renderSceneText(furnaceText(f)).film(), furnaceValue(f.albedo, 1000));
    EXPECT_LE(deviation, 4096 * floatSpacing(f)) << describe(f);
    worst = std::max(worst, deviation);
  }
  test::recordFigure(
      "furnace sphere, Kd 0.999, volpath maxdepth 1000: every pixel within "
      "4096 eps of (1 - 0.999^1001) / 0.001",
      "worst pixel %.2g of 632.67", worst);
}

}  // namespace
}  // namespace candela
