// Light sampling (lrt draft §15.4): for every non-delta light, the histogram of sampleLi's
// directions matches pdfLi (chi-square over a θ x φ grid, cells expected below 5 pooled), and
// pdfLi integrates to 1 over the directions the light covers. Significance 0.01 over all cases
// with a Šidák correction; fixed seeds.
#include <gtest/gtest.h>

#include <memory>

#include "direction_stats.h"
#include "lights/diffuse_area_light.h"
#include "lights/infinite_light.h"
#include "shapes/disk.h"
#include "shapes/sphere.h"
#include "shapes/triangle_mesh.h"

namespace candela {
namespace {

constexpr int kCases = 9;  // the chi-square cases below, for the Šidák correction
constexpr int64_t kSamples = 200000;

// One bright patch (100x the background) on a 32 x 16 map, away from the poles.
LatLongMap patchMap() {
  LatLongMap m{32, 16, std::vector<Spectrum>(32 * 16, Spectrum(0.05f))};
  for (int j = 5; j < 8; ++j)
    for (int i = 20; i < 24; ++i) m.texels[size_t(j) * 32 + size_t(i)] = Spectrum(5, 4, 2);
  return m;
}

stats::FitResult fitLight(const Light& light, const Point3f& p, uint64_t seed, int nTheta,
                          int nPhi) {
  Interaction ref(p, 0);
  return stats::chiSquareFit(
      [&](Float, const Point2f& u, Vector3f* w) {
        Float pdf;
        VisibilityTester vis;
        light.sampleLi(ref, u, w, &pdf, &vis);
        return pdf > 0;
      },
      [&](const Vector3f& w) { return double(light.pdfLi(ref, w)); }, kSamples, seed, nTheta, nPhi);
}

class LightSampling : public ::testing::Test {
 protected:
  void check(const Light& light, const Point3f& p, uint64_t seed, int nTheta = 20, int nPhi = 40) {
    stats::FitResult r = fitLight(light, p, seed, nTheta, nPhi);
    SCOPED_TRACE(r.summary());
    EXPECT_GT(r.pValue, stats::sidak(0.01, kCases));
    EXPECT_EQ(r.failed, 0);
    EXPECT_NEAR(r.pdfIntegral, 1, 1e-3);
  }
};

TEST_F(LightSampling, SphereOutsideUsesTheCone) {
  SphereShape sphere(translate(Vector3f(0.3f, -0.2f, 2)), false, 0.7f, -0.7f, 0.7f, 360);
  DiffuseAreaLight light(&sphere, Spectrum(1), 1, false);
  check(light, Point3f(0, 0, 0), 101);
}

TEST_F(LightSampling, SphereFromInside) {
  SphereShape sphere(Transform(), true, 1, -1, 1, 360);
  DiffuseAreaLight light(&sphere, Spectrum(1), 1, false);
  check(light, Point3f(0.2f, 0.1f, -0.3f), 102);
}

TEST_F(LightSampling, Disk) {
  DiskShape disk(rotateX(30), false, 1, 1.5f, 0, 360);
  DiffuseAreaLight light(&disk, Spectrum(1), 1, true);
  check(light, Point3f(0.4f, 0, -0.5f), 103);
}

TEST_F(LightSampling, PartialAnnulus) {
  DiskShape disk(Transform(), false, 0.5f, 1, 0.4f, 270);
  DiffuseAreaLight light(&disk, Spectrum(1), 1, true);
  check(light, Point3f(0.1f, 0.2f, 0), 104);
}

TEST_F(LightSampling, Triangle) {
  TriangleMesh mesh(Transform(), false, {0, 1, 2},
                    {{-1, -0.5f, 1}, {1.5f, -0.3f, 0.8f}, {0, 1, 1.4f}});
  std::vector<std::unique_ptr<Shape>> tris = createTriangleShapes(&mesh);
  DiffuseAreaLight light(tris[0].get(), Spectrum(1), 1, true);
  check(light, Point3f(0, 0, 0), 105);
}

TEST_F(LightSampling, InfiniteUniform) {
  InfiniteAreaLight light(rotateY(40), Spectrum(1), 1, {});
  check(light, Point3f(0, 0, 0), 106);
}

// The map cases use a histogram aligned with the map's 32 x 16 texels: the pdf is then constant
// in each (θ, φ) cell and its cubature is cheap; the rotation keeps the texel borders aligned
// (45° about z is four texel columns; 180° about x mirrors θ and φ), so a wrong transform moves
// the patch by whole cells and fails.
TEST_F(LightSampling, InfiniteWithMap) {
  InfiniteAreaLight light(Transform(), Spectrum(1), 1, patchMap());
  check(light, Point3f(0, 0, 0), 107, 16, 32);
}

TEST_F(LightSampling, InfiniteWithAlignedRotatedMap) {
  InfiniteAreaLight light(rotateZ(45) * rotateX(180), Spectrum(1), 1, patchMap());
  check(light, Point3f(1, 2, 3), 108, 16, 32);
}

// An arbitrary rotation: texel borders cross the histogram's cells (slow cubature; label "long").
class LongLightSampling : public LightSampling {};
TEST_F(LongLightSampling, InfiniteWithRotatedMap) {
  InfiniteAreaLight light(rotate(70, Vector3f(1, 1, 0)), Spectrum(1), 1, patchMap());
  check(light, Point3f(1, 2, 3), 110);
}

// The sampled texel frequencies against the map itself: texel (i, j) is chosen with probability
// proportional to sin θ_j (§15.4) times the largest luminance of it and its eight neighbours (the
// texels its interpolated radiance comes from; periodic in φ, clamped at the poles). One
// chi-square over the 512 texels (pooled below 5 expected).
TEST(LightSamplingMap, TexelFrequenciesFollowLuminanceTimesSinTheta) {
  LatLongMap map = patchMap();
  InfiniteAreaLight light(Transform(), Spectrum(1), 1, map);
  std::vector<double> weight(map.texels.size()), observed(map.texels.size(), 0);
  double total = 0;
  for (int j = 0; j < map.height; ++j)
    for (int i = 0; i < map.width; ++i) {
      size_t k = size_t(j) * size_t(map.width) + size_t(i);
      double largest = 0;
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          int ii = (i + di + map.width) % map.width;
          int jj = std::clamp(j + dj, 0, map.height - 1);
          largest = std::max(largest,
                             double(map.texels[size_t(jj) * size_t(map.width) + size_t(ii)].y()));
        }
      weight[k] = largest * std::sin(M_PI * (j + 0.5) / map.height);
      total += weight[k];
    }
  RNG rng(109);
  Interaction ref(Point3f(0, 0, 0), 0);
  for (int64_t s = 0; s < kSamples; ++s) {
    Vector3f w;
    Float pdf;
    VisibilityTester vis;
    light.sampleLi(ref, Point2f(rng.uniformFloat(), rng.uniformFloat()), &w, &pdf, &vis);
    ASSERT_GT(pdf, 0);
    double phi = std::atan2(double(w.y), double(w.x));
    if (phi < 0) phi += 2 * M_PI;
    int i = std::min(map.width - 1, int(phi / (2 * M_PI) * map.width));
    int j = std::min(map.height - 1,
                     int(std::acos(std::clamp(double(w.z), -1.0, 1.0)) / M_PI * map.height));
    observed[size_t(j) * size_t(map.width) + size_t(i)] += 1;
  }
  double chi2 = 0, poolO = 0, poolE = 0;
  int cells = 0;
  for (size_t k = 0; k < weight.size(); ++k) {
    double e = weight[k] / total * double(kSamples);
    if (e < 5) {
      poolO += observed[k];
      poolE += e;
      continue;
    }
    chi2 += (observed[k] - e) * (observed[k] - e) / e;
    ++cells;
  }
  if (poolE >= 5) {
    chi2 += (poolO - poolE) * (poolO - poolE) / poolE;
    ++cells;
  }
  double p = stats::chiSquareSurvival(chi2, cells - 1);
  EXPECT_GT(p, 0.01) << "chi2 " << chi2 << " over " << cells << " cells";
  // The patch (12 of 512 texels, 100x brighter than the rest) and the ring of texels its light is
  // interpolated into (30 in all) take most samples.
  double patch = 0;
  for (int j = 4; j < 9; ++j)
    for (int i = 19; i < 25; ++i) patch += observed[size_t(j) * 32 + size_t(i)];
  EXPECT_GT(patch / double(kSamples), 0.8);
}

}  // namespace
}  // namespace candela
