// A closed form for light that reaches a diffuse floor only by perfect specular reflection: a
// small spherical light over a matte floor, beside a wall-sized perfect mirror (Kr = 1). The
// mirror adds the light of the light's mirror image, so the irradiance at a floor point x is
//   E(x) = π L r² (cos θ / d² + cos θ' / d'²)
// (a sphere of radiance L and radius r entirely above the plane acts as a point of intensity
// π r² L), with d, θ for the light and d', θ' for its image; the floor's radiance is ρ E / π. The
// camera looks down on the floor, so each pixel's expected value is the mean of that over its
// area, found here by quadrature through the scene's own camera (a box filter samples the pixel
// uniformly). The mirror light is what bidirectional methods find by light tracing and what a
// path tracer finds only by BSDF sampling through the mirror; both must meet it, as the caustic
// scene's glass does (test_bdpt_vs_path.cpp).
//
// The statistic: for each of the 16 regions of a 4 x 4 grid over the image, the mean of
// independent replicate renders (seeds 1..n) against the region's exact mean, by the z of the
// replicates' standard error. Per region significance: Šidák 0.01 over the 16 regions (normal
// approximation; with n = 24 replicates the Student tails make the family-wise level about 0.03).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "support/render_scene.h"
#include "support/tail_probabilities.h"

namespace candela {
namespace {

constexpr int kResolution = 16;
constexpr int kRegions = 4;
// The light's power goes as L r²: lights of other radii keep it.
constexpr double kRadiantExitanceScale = 0.5;  // L r²
constexpr double kAlbedo = 0.5;
const Point3f kLight(0, 1, 1.2f);
constexpr double kMirrorX = 1;

std::string sceneText(const std::string& integrator, double radius) {
  std::string L = std::to_string(kRadiantExitanceScale / (radius * radius));
  std::string r = std::to_string(radius);
  return "LookAt -0.2 3 0  -0.2 0 0  0 0 1\n"
         "Camera \"perspective\" \"float fov\" [40]\n"
         "Film \"image\" \"integer xresolution\" [16] \"integer yresolution\" [16]\n"
         "PixelFilter \"box\"\n"
         "Sampler \"random\"\n" +
         integrator +
         "\nWorldBegin\n"
         "AttributeBegin\n"
         "  Translate 0 1 1.2\n"
         "  AreaLightSource \"diffuse\" \"rgb L\" [" +
         L + " " + L + " " + L +
         "]\n"
         "  Material \"matte\" \"rgb Kd\" [0 0 0]\n"
         "  Shape \"sphere\" \"float radius\" [" +
         r +
         "]\n"
         "AttributeEnd\n"
         "Material \"matte\" \"rgb Kd\" [0.5 0.5 0.5]\n"
         "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3]\n"
         "  \"point P\" [-20 0 -20  1 0 -20  1 0 20  -20 0 20]\n"
         "Material \"mirror\" \"rgb Kr\" [1 1 1]\n"
         "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3]\n"
         "  \"point P\" [1 0 -20  1 20 -20  1 20 20  1 0 20]\n"
         "WorldEnd\n";
}

// The floor's exact radiance at x (y = 0, x < the mirror).
double floorRadiance(double x, double z) {
  auto fromPoint = [&](double cx) {
    double dx = cx - x, dy = kLight.y, dz = kLight.z - z;
    double d2 = dx * dx + dy * dy + dz * dz;
    return (dy / std::sqrt(d2)) / d2;
  };
  double e =
      kPi * kRadiantExitanceScale * (fromPoint(kLight.x) + fromPoint(2 * kMirrorX - kLight.x));
  return kAlbedo * kInvPi * e;
}

// The exact mean of each region, by a 16 x 16 midpoint rule over every pixel.
std::vector<double> exactRegionMeans(const Camera& camera) {
  constexpr int kQuad = 16;
  const int size = kResolution / kRegions;
  std::vector<double> means(kRegions * kRegions, 0);
  for (int py = 0; py < kResolution; ++py)
    for (int px = 0; px < kResolution; ++px) {
      double sum = 0;
      for (int j = 0; j < kQuad; ++j)
        for (int i = 0; i < kQuad; ++i) {
          CameraSample cs;
          cs.pFilm = Point2f(px + (i + 0.5f) / kQuad, py + (j + 0.5f) / kQuad);
          cs.pLens = Point2f(0.5f, 0.5f);
          Ray ray;
          camera.generateRay(cs, &ray);
          // Only the floor is in view (checked: the light and mirror are outside the frustum).
          EXPECT_LT(ray.d.y, 0);
          double t = -ray.o.y / ray.d.y;
          double x = ray.o.x + t * ray.d.x, z = ray.o.z + t * ray.d.z;
          EXPECT_LT(x, kMirrorX - 0.05);
          sum += floorRadiance(x, z);
        }
      means[(py / size) * kRegions + px / size] += sum / (kQuad * kQuad) / (size * size);
    }
  return means;
}

// Renders `replicates` times at spp and holds every region to the exact mean: by the z test, and
// with a standard error below maxRelativeError of the exact value, so that the test has the power
// to see an error of 4 maxRelativeError (4 standard errors) rather than passing on noise.
void expectMeetsClosedForm(const std::string& integrator, double lightRadius, int replicates,
                           int spp, double maxRelativeError = 0.025) {
  SCOPED_TRACE(integrator);
  std::string text = sceneText(integrator, lightRadius);
  std::vector<double> exact = exactRegionMeans(*test::buildSceneText(text).job().camera);
  const int size = kResolution / kRegions, n = kRegions * kRegions;
  std::vector<double> sum(n, 0), sumSq(n, 0);
  for (int rep = 0; rep < replicates; ++rep) {
    test::TestRenderOptions o;
    o.build.sppOverride = spp;
    o.build.seed = uint64_t(rep + 1);
    auto r = test::renderSceneText(text, o);
    for (int k = 0; k < n; ++k) {
      double m = 0;
      for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
          m += r.film()
                   .pixelValue(Point2i((k % kRegions) * size + x, (k / kRegions) * size + y))
                   .y();
      m /= size * size;
      sum[k] += m;
      sumSq[k] += m * m;
    }
  }
  double worstRelativeError = 0;
  for (int k = 0; k < n; ++k) {
    double mean = sum[k] / replicates;
    double se = std::sqrt((sumSq[k] - replicates * mean * mean) / (replicates - 1) / replicates);
    double z = (mean - exact[k]) / se;
    EXPECT_GT(stats::normalTwoSidedTail(z), stats::sidak(0.01, n))
        << "region " << k << ": " << mean << " against exact " << exact[k] << ", z " << z;
    EXPECT_LT(se, maxRelativeError * exact[k]) << "region " << k << ": too noisy to tell";
    worstRelativeError = std::max(worstRelativeError, std::abs(mean / exact[k] - 1));
  }
  ::testing::Test::RecordProperty("worst_relative_error", std::to_string(worstRelativeError));
}

// The light of radius 0.1 that the bidirectional methods take: a path tracer finds its mirror
// image only by BSDF sampling, about once in a thousand floor samples, too rarely for a replicate
// variance to mean much at these counts; a light of radius 0.4 with the same power (and so the
// same closed form) it finds sixteen times as often.
constexpr double kSmallLight = 0.1, kLargeLight = 0.4;

TEST(MirrorCaustic, PathTracingMeetsTheClosedForm) {
  expectMeetsClosedForm("SurfaceIntegrator \"path\" \"integer maxdepth\" [5]", kLargeLight, 24,
                        256);
}

TEST(MirrorCaustic, BidirectionalMeetsTheClosedForm) {
  expectMeetsClosedForm("Integrator \"bdpt\" \"integer maxdepth\" [5]", kSmallLight, 24, 128);
}

// Metropolis spends its mutations where the image is bright, so its dim regions are the noisy
// ones, and each chain starts from one bootstrap path: with 64 chains of 2048 mutations the
// darkest region (region 15, a sixth of the brightest) still came out 7.6% low (z -4.3, 24
// replicates), so only the Long suite, with chains four times as long, holds Metropolis to the
// closed form here; the normal suite's Metropolis tests are the furnace, the analytic cases and
// the region agreement with path.
std::string mlt(int bootstrap) {
  return "Integrator \"mlt\" \"integer maxdepth\" [5] \"integer chains\" [64] "
         "\"integer bootstrapsamples\" [" +
         std::to_string(bootstrap) + "]";
}
// pbrt-v2's renderer in 16 chains of 32,768 mutations: with 64 chains of 8,192 its darkest region
// (15) read 3.6 %, 0.9 % and 1.6 % low for replicate seeds 1-32, 101-132 and 201-232 (z -4.2, -0.9,
// -1.5: the start-up bias above), with 16 chains 0.7 % low, 0.3 % low and 0.4 % high, every
// region within |z| 2.4. (pbrt-v3's mlt keeps 64: its small steps explore more slowly, and with 4
// chains its regions were too noisy to tell.)
std::string metropolis(int bootstrap) {
  return "Renderer \"metropolis\" \"integer maxdepth\" [5] \"integer chains\" [16] "
         "\"integer bootstrapsamples\" [" +
         std::to_string(bootstrap) + "]";
}

TEST(LongMirrorCaustic, MetropolisMeetsTheClosedForm) {
  expectMeetsClosedForm(mlt(20000), kSmallLight, 32, 2048, 0.03);
}

TEST(LongMirrorCaustic, PbrtV2MetropolisMeetsTheClosedForm) {
  expectMeetsClosedForm(metropolis(20000), kSmallLight, 32, 2048, 0.03);
}

}  // namespace
}  // namespace candela
