// Photon storage, nearest-photon queries and density estimation (pbrt 2e §15.6.2) against closed
// forms for known photon distributions.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/rng.h"
#include "reflection/point_kdtree.h"
#include "transport/photon_density.h"

namespace candela {
namespace {

SurfaceInteraction planeAt(const Point3f& p, const Vector3f& wo) {
  return SurfaceInteraction(p, Vector3f(), Point2f(0, 0), wo, Vector3f(1, 0, 0), Vector3f(0, 1, 0),
                            Normal3f(), Normal3f(), 0, false);
}

// Photons on the plane z = 0 at the points of a square lattice of spacing h, turned by an
// irrational angle and shifted so that no two lie at the same distance from the lookup points.
std::vector<Photon> latticePhotons(Float h, Float extent, const Spectrum& alpha,
                                   bool fromAbove = true) {
  std::vector<Photon> photons;
  Float c = std::cos(Float(0.3)), s = std::sin(Float(0.3));
  int n = int(extent / h);
  RNG rng(7);
  for (int i = -n; i <= n; ++i)
    for (int j = -n; j <= n; ++j) {
      Float x = (i + Float(0.31)) * h, y = (j + Float(0.17)) * h;
      // Incident directions vary; a Lambertian BRDF does not care.
      Float z = Float(0.2) + Float(0.8) * rng.uniformFloat();
      Float phi = 2 * kPi * rng.uniformFloat();
      Float r = std::sqrt(1 - z * z);
      Vector3f wi(r * std::cos(phi), r * std::sin(phi), fromAbove ? z : -z);
      photons.push_back(Photon{Point3f(c * x - s * y, s * x + c * y, 0), alpha, wi});
    }
  return photons;
}

TEST(PointKdTree, QueriesAgreeWithBruteForce) {
  RNG rng(3);
  std::vector<PointKdTree<3>::Point> points(2000);
  for (auto& p : points) p = {rng.uniformFloat(), rng.uniformFloat(), rng.uniformFloat()};
  PointKdTree<3> tree(points);
  for (int trial = 0; trial < 50; ++trial) {
    PointKdTree<3>::Point q = {rng.uniformFloat(), rng.uniformFloat(), rng.uniformFloat()};
    Float maxDist2 = Float(0.002) + Float(0.01) * rng.uniformFloat();
    auto even = [](uint32_t i) { return i % 2 == 0; };
    std::vector<std::pair<Float, uint32_t>> all, evens;
    for (uint32_t i = 0; i < points.size(); ++i) {
      Float d2 = 0;
      for (int a = 0; a < 3; ++a) d2 += (points[i][a] - q[a]) * (points[i][a] - q[a]);
      if (d2 < maxDist2) {
        all.push_back({d2, i});
        if (even(i)) evens.push_back({d2, i});
      }
    }
    std::sort(all.begin(), all.end());
    std::sort(evens.begin(), evens.end());
    const int k = 12;
    uint32_t idx[k];
    Float d2[k];
    int found = tree.nearestWithin(q, k, maxDist2, idx, d2);
    ASSERT_EQ(found, std::min<int>(k, int(all.size())));
    for (int i = 0; i < found; ++i) EXPECT_EQ(idx[i], all[i].second);
    found = tree.nearestMatching(q, k, maxDist2, even, idx, d2);
    ASSERT_EQ(found, std::min<int>(k, int(evens.size())));
    for (int i = 0; i < found; ++i) EXPECT_EQ(idx[i], evens[i].second);
    // The fixed-radius query visits every point inside, each once, with the same distance.
    std::vector<std::pair<Float, uint32_t>> visited;
    tree.forEachWithin(q, maxDist2, [&](uint32_t i, Float d) { visited.push_back({d, i}); });
    std::sort(visited.begin(), visited.end());
    EXPECT_EQ(visited, all);
  }
}

TEST(PhotonMap, NearestReturnsPhotonsInOrderWithinTheRadius) {
  std::vector<Photon> photons;
  for (int i = 0; i < 10; ++i)
    photons.push_back(Photon{Point3f(Float(i), 0, 0), Spectrum(1), Vector3f(0, 0, 1)});
  PhotonMap map(photons, 5);
  EXPECT_EQ(map.size(), 10u);
  EXPECT_EQ(map.nPaths(), 5u);
  EXPECT_GT(map.memoryBytes(), 10 * sizeof(Photon));
  NearPhoton out[4];
  int found = map.nearest(Point3f(4.1f, 0, 0), 2.5f * 2.5f, out);
  ASSERT_EQ(found, 4);  // x = 4, 5, 3, 6 (2 is at distance 2.1, 7 at 2.9)
  EXPECT_EQ(out[0].photon->p.x, 4);
  EXPECT_EQ(out[1].photon->p.x, 5);
  EXPECT_EQ(out[2].photon->p.x, 3);
  EXPECT_EQ(out[3].photon->p.x, 6);
  EXPECT_NEAR(out[0].dist2, 0.01f, 1e-5f);
}

TEST(PhotonDensity, SimpsonKernelIntegratesToOneOverTheDisc) {
  // Midpoint rule in the radius: 2 pi int_0^r K(t^2) t dt.
  const Float r2 = 0.25f;
  double sum = 0;
  const int n = 100000;
  double r = std::sqrt(r2);
  for (int i = 0; i < n; ++i) {
    double t = (i + 0.5) / n * r;
    sum += simpsonKernel(Float(t * t), r2) * 2 * kPi * t * (r / n);
  }
  EXPECT_NEAR(sum, 1.0, 1e-6);
  EXPECT_EQ(simpsonKernel(0.3f, r2), 0);
}

// A uniform density of sigma photons per unit area, each of weight alpha out of nPaths paths,
// is irradiance E = sigma alpha / nPaths; a Lambertian surface of reflectance rho then reflects
// L = rho / pi E in every direction.
TEST(PhotonDensity, UniformPhotonsOnADiffusePlaneGiveTheClosedFormRadiance) {
  const Float h = 0.002f, maxDist = 0.05f;
  const Spectrum alpha(0.5f, 1.0f, 2.0f), rho(0.8f, 0.5f, 0.25f);
  const uint64_t nPaths = 1000;
  PhotonMap map(latticePhotons(h, 0.2f, alpha), nPaths);
  MemoryArena arena;
  const Point3f p(0.013f, -0.021f, 0);
  for (Vector3f wo : {Vector3f(0, 0, 1), normalize(Vector3f(0.6f, 0.2f, 0.5f))}) {
    SurfaceInteraction si = planeAt(p, wo);
    BSDF bsdf(si);
    LambertianReflection lambert(rho);
    bsdf.add(&lambert);
    Spectrum expected = rho / kPi * alpha / (h * h * Float(nPaths));
    // Every photon within maxdist is used (about 2000), so the disc is exactly maxdist: the sum
    // of the C1 kernel over the lattice differs from its integral by far less than 0.1%.
    DensityEstimate all{100000, maxDist * maxDist, 0};
    Spectrum l = photonRadiance(map, p, wo, bsdf, all, arena);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(l[c] / expected[c], 1, 1e-4) << c;
    // The nused nearest only: the disc shrinks to the 500th photon, where the kernel is 0, so
    // the smooth kernel's sum stays as close (measured 1e-6; 1e-3 allowed).
    DensityEstimate nearest{500, maxDist * maxDist, 0};
    l = photonRadiance(map, p, wo, bsdf, nearest, arena);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(l[c] / expected[c], 1, 1e-3) << c;
    // Irradiance, with a constant kernel over that disc: 500 photons over pi r^2 counts lattice
    // points in a disc, whose error is O(k^-3/4) (measured 0.1%; 1% allowed).
    Spectrum e = photonIrradiance(map, p, Normal3f(0, 0, 1), nearest, arena);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(e[c] / (alpha[c] / (h * h * Float(nPaths))), 1, 0.01) << c;
  }
}

TEST(PhotonDensity, PhotonsFromBehindDoNotLightTheFront) {
  const Float h = 0.005f;
  PhotonMap map(latticePhotons(h, 0.2f, Spectrum(1), false), 10);
  MemoryArena arena;
  SurfaceInteraction si = planeAt(Point3f(0, 0, 0), Vector3f(0, 0, 1));
  BSDF bsdf(si);
  LambertianReflection lambert(Spectrum(0.5f));
  bsdf.add(&lambert);
  DensityEstimate est{50, 0.01f, 0};
  EXPECT_TRUE(photonRadiance(map, si.p, si.wo, bsdf, est, arena).isBlack());
  EXPECT_TRUE(photonIrradiance(map, si.p, Normal3f(0, 0, 1), est, arena).isBlack());
  EXPECT_FALSE(photonIrradiance(map, si.p, Normal3f(0, 0, -1), est, arena).isBlack());
}

TEST(PhotonDensity, NFilterDropsTheBrightestPhotons) {
  const Float h = 0.002f;
  std::vector<Photon> photons = latticePhotons(h, 0.2f, Spectrum(1));
  // One photon a thousand times too bright right at the lookup point.
  photons.push_back(Photon{Point3f(0, 0, 0), Spectrum(1000), Vector3f(0, 0, 1)});
  PhotonMap map(photons, 1);
  MemoryArena arena;
  SurfaceInteraction si = planeAt(Point3f(0, 0, 0), Vector3f(0, 0, 1));
  BSDF bsdf(si);
  LambertianReflection lambert(Spectrum(1));
  bsdf.add(&lambert);
  Float expected = 1 / (kPi * h * h);
  Float unfiltered = photonRadiance(map, si.p, si.wo, bsdf, {200, 1, 0}, arena)[0];
  Float filtered = photonRadiance(map, si.p, si.wo, bsdf, {200, 1, 8}, arena)[0];
  EXPECT_GT(unfiltered / expected, 2);
  // Dropping 8 of 200 (the bright one and 7 ordinary ones near the rim or the centre) and
  // scaling by 200/192 leaves a few percent of bias (measured 3%; 5% allowed).
  EXPECT_NEAR(filtered / expected, 1, 0.05);
}

TEST(PhotonDensity, EmptyMapsAndNoPhotonsNearbyGiveZero) {
  MemoryArena arena;
  SurfaceInteraction si = planeAt(Point3f(0, 0, 0), Vector3f(0, 0, 1));
  BSDF bsdf(si);
  LambertianReflection lambert(Spectrum(1));
  bsdf.add(&lambert);
  EXPECT_TRUE(photonRadiance(PhotonMap(), si.p, si.wo, bsdf, {}, arena).isBlack());
  PhotonMap far({Photon{Point3f(5, 0, 0), Spectrum(1), Vector3f(0, 0, 1)}}, 1);
  EXPECT_TRUE(photonRadiance(far, si.p, si.wo, bsdf, {50, 0.01f, 0}, arena).isBlack());
}

}  // namespace
}  // namespace candela
