// pbrt-v3 named media and the tracking routines (src/media/tracking): closed-form homogeneous
// transmittance, the grid's trilinear interpolation, and delta and ratio tracking against
// ray-marched transmittance through a smooth heterogeneous density.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "media/grid_density_medium.h"
#include "media/homogeneous_medium.h"
#include "media/tracking.h"
#include "support/tail_probabilities.h"

namespace candela {
namespace {

TEST(HomogeneousMedium, TransmittanceIsExpOfMinusSigmaTTimesDistance) {
  Spectrum sigmaA(0.1f, 0.2f, 0.3f), sigmaS(0.5f, 1.0f, 2.0f);
  HomogeneousMedium m(sigmaA, sigmaS, 0.3f);
  RNG rng(1);
  for (Float length : {0.5f, 3.0f}) {
    for (Float tMax : {0.25f, 1.0f, 7.0f}) {
      // Direction of any length: the distance is tMax * |d|.
      Ray ray(Point3f(1, 2, 3), normalize(Vector3f(1, -2, 0.5f)) * length, tMax);
      Spectrum tr = trackedTransmittance(m, ray, rng);
      for (int c = 0; c < 3; ++c) {
        double expected = std::exp(-double(sigmaA[c] + sigmaS[c]) * tMax * length);
        EXPECT_NEAR(tr[c], expected, 2e-6 * expected + 1e-7) << "channel " << c;
      }
    }
  }
  // An unbounded segment through a medium with σt = 0 in one channel passes that channel only.
  HomogeneousMedium partial(Spectrum(0), Spectrum(0, 1, 1), 0);
  Spectrum tr = trackedTransmittance(partial, Ray(Point3f(0, 0, 0), Vector3f(0, 0, 1)), rng);
  EXPECT_EQ(tr, Spectrum(1, 0, 0));
}

// A 4 x 3 x 2 grid whose values tell their indices apart.
GridDensityMedium indexGrid(const Transform& toWorld = Transform()) {
  std::vector<Float> d;
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 4; ++x) d.push_back(Float(1 + x + 10 * y + 100 * z));
  return GridDensityMedium(Spectrum(1), Spectrum(2), 0, 4, 3, 2, d, Point3f(-1, 0, 2),
                           Point3f(3, 3, 4), toWorld);
}

TEST(GridDensityMedium, CellCentresReturnTheStoredValues) {
  GridDensityMedium g = indexGrid();
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 4; ++x) {
        Point3f centre((x + 0.5f) / 4, (y + 0.5f) / 3, (z + 0.5f) / 2);
        EXPECT_FLOAT_EQ(g.density(centre), Float(1 + x + 10 * y + 100 * z)) << x << y << z;
      }
  // Halfway between two centres along x: their mean (trilinear, not nearest).
  EXPECT_FLOAT_EQ(g.density(Point3f(1.0f / 4, 0.5f / 3, 0.25f)), 1.5f);
  // In world space (medium space here): σt = (1 + 2) * density at the centre of cell (2, 1, 0),
  // which sits at p0 + (2.5, 1.5, 0.5) * (1, 1, 1).
  MediumPoint mp = g.at(Point3f(1.5f, 1.5f, 2.5f), 0);
  EXPECT_FLOAT_EQ(mp.sigmaT()[0], 3 * Float(1 + 2 + 10));
}

TEST(GridDensityMedium, OutsideTheGridIsZero) {
  GridDensityMedium g = indexGrid();
  for (Point3f p : {Point3f(-1.5f, 0.5f, 0.5f), Point3f(0.5f, 1.6f, 0.5f),
                    Point3f(0.5f, 0.5f, -0.3f), Point3f(4, 4, 4), Point3f(1e30f, 0, 0)})
    EXPECT_EQ(g.density(p), 0) << p.x << " " << p.y << " " << p.z;
  EXPECT_EQ(g.at(Point3f(-2, 1, 3), 0).sigmaT(), Spectrum(0));
  EXPECT_EQ(g.at(Point3f(1, 1, 5), 0).sigmaT(), Spectrum(0));
}

TEST(GridDensityMedium, LivesInItsOwnCoordinateSystem) {
  // Moved by (10, 0, 0) and scaled by 2: the stored value of cell (0, 0, 0) sits at
  // 2 * (p0 + (0.5, 0.5, 0.5)) + (10, 0, 0).
  Transform toWorld = translate(Vector3f(10, 0, 0)) * scale(2, 2, 2);
  GridDensityMedium g = indexGrid(toWorld);
  EXPECT_FLOAT_EQ(g.at(Point3f(9, 1, 5), 0).sigmaS[0], 2 * 1.0f);
  Float t0, t1;
  ASSERT_TRUE(g.intersectP(Ray(Point3f(0, 1, 5), Vector3f(1, 0, 0)), &t0, &t1));
  EXPECT_NEAR(t0, 8, 1e-5);
  EXPECT_NEAR(t1, 16, 1e-5);
  EXPECT_FALSE(g.intersectP(Ray(Point3f(0, 1, 5), Vector3f(-1, 0, 0)), &t0, &t1));
  EXPECT_FALSE(g.intersectP(Ray(Point3f(0, 1, 5), Vector3f(1, 0, 0), 7.5f), &t0, &t1));
}

// A smooth density on a 24^3 grid over [0,1]^3: a Gaussian blob on a floor.
GridDensityMedium smoothGrid(const Spectrum& sigmaA, const Spectrum& sigmaS) {
  const int n = 24;
  std::vector<Float> d;
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        Float px = (x + 0.5f) / n - 0.5f, py = (y + 0.5f) / n - 0.4f, pz = (z + 0.5f) / n - 0.5f;
        d.push_back(0.2f + 2 * std::exp(-(px * px + py * py + pz * pz) / 0.05f));
      }
  return GridDensityMedium(sigmaA, sigmaS, 0, n, n, n, d, Point3f(0, 0, 0), Point3f(1, 1, 1),
                           Transform());
}

// Rays through the grid at various angles, some ending inside it.
std::vector<Ray> testRays() {
  return {Ray(Point3f(-0.5f, 0.5f, 0.5f), Vector3f(1, 0, 0)),
          Ray(Point3f(-0.2f, -0.1f, 0.3f), Vector3f(1, 1.2f, 0.4f)),
          Ray(Point3f(0.5f, 0.4f, -1), Vector3f(0, 0, 2), 0.75f)};
}

// The sample mean of n estimates and its standard error.
struct MeanEstimate {
  double mean[3] = {}, stdError[3] = {};
};
template <typename Estimate>
MeanEstimate estimateMean(int n, Estimate estimate) {
  double sum[3] = {}, sumSq[3] = {};
  for (int i = 0; i < n; ++i) {
    Spectrum v = estimate();
    for (int c = 0; c < 3; ++c) {
      sum[c] += v[c];
      sumSq[c] += double(v[c]) * v[c];
    }
  }
  MeanEstimate m;
  for (int c = 0; c < 3; ++c) {
    m.mean[c] = sum[c] / n;
    m.stdError[c] = std::sqrt(std::max(0.0, sumSq[c] / n - m.mean[c] * m.mean[c]) / (n - 1));
  }
  return m;
}

// Each check: the tracked mean against the marched reference (10^4 steps: its own error is below
// 1e-4, far under the tracking's standard error), two-sided at Šidák 0.001 over all checks of the
// suite (45 channel checks). Estimates are bounded in [0, 1] or nearly so, so
// with 20,000 samples the normal approximation of the mean holds.
constexpr int kChecks = 45;
constexpr int kSamples = 20000;
void expectAgrees(const MeanEstimate& m, const Spectrum& reference, const char* what) {
  for (int c = 0; c < 3; ++c) {
    double z = (m.mean[c] - reference[c]) / std::max(m.stdError[c], 1e-9);
    EXPECT_GT(stats::normalTwoSidedTail(z), stats::sidak(0.001, kChecks))
        << what << " channel " << c << ": " << m.mean[c] << " vs marched " << reference[c] << " (z "
        << z << ")";
  }
}

TEST(Tracking, RatioTrackingAgreesWithRayMarching) {
  GridDensityMedium g = smoothGrid(Spectrum(0.5f, 1, 2), Spectrum(1, 1.5f, 0.5f));
  RNG rng(7);
  for (const Ray& ray : testRays()) {
    Spectrum reference = marchedTransmittance(g, ray, 10000);
    EXPECT_GT(reference.maxComponent(), 0.05f);  // the rays see something of the medium
    EXPECT_LT(reference.maxComponent(), 0.95f);
    expectAgrees(estimateMean(kSamples, [&] { return trackedTransmittance(g, ray, rng); }),
                 reference, "ratio tracking");
  }
}

TEST(Tracking, DeltaTrackingEscapeAgreesWithRayMarching) {
  // Without absorption the flight's weight is 1 and it escapes with probability T: classic delta
  // tracking (Woodcock). With chromatic σ and absorption, spectral tracking's escape weight has
  // expectation T per channel.
  RNG rng(11);
  for (bool chromatic : {false, true}) {
    GridDensityMedium g = chromatic ? smoothGrid(Spectrum(0.5f, 1, 0), Spectrum(1, 1.5f, 0.5f))
                                    : smoothGrid(Spectrum(0), Spectrum(2));
    for (const Ray& ray : testRays()) {
      Spectrum reference = marchedTransmittance(g, ray, 10000);
      // The chromatic case with a lopsided path throughput (channels favoured unevenly).
      Spectrum throughput = chromatic ? Spectrum(3, 1, 0.2f) : Spectrum(1);
      auto escaped = [&] {
        FreeFlight f = sampleFreeFlight(g, ray, rng, throughput);
        if (!chromatic) {
          // 1 up to float rounding: a few ulps for each of the flight's null collisions.
          EXPECT_NEAR(f.weight[0], 1, 1e-4);
        }
        return f.scattered ? Spectrum(0) : f.weight;
      };
      expectAgrees(estimateMean(kSamples, escaped), reference,
                   chromatic ? "spectral tracking" : "delta tracking");
    }
  }
}

TEST(Tracking, HomogeneousFreeFlightIsUnbiased) {
  // The closed-form flight: E[escape weight] = T, and E[scatter weight] = ∫ T σs dt = σs/σt (1-T).
  Spectrum sigmaA(0.2f, 0.5f, 0), sigmaS(1, 0.5f, 2);
  HomogeneousMedium m(sigmaA, sigmaS, 0);
  Ray ray(Point3f(0, 0, 0), Vector3f(0, 0, 1), 0.8f);
  RNG rng(3);
  Spectrum t = trackedTransmittance(m, ray, rng);
  Spectrum scattered;
  for (int c = 0; c < 3; ++c) scattered[c] = sigmaS[c] / (sigmaA[c] + sigmaS[c]) * (1 - t[c]);
  // Any throughput that picks the channels is unbiased: uniform, and a lopsided one.
  for (Spectrum throughput : {Spectrum(1), Spectrum(0.1f, 1, 5)}) {
    MeanEstimate escape = estimateMean(kSamples, [&] {
      FreeFlight f = sampleFreeFlight(m, ray, rng, throughput);
      return f.scattered ? Spectrum(0) : f.weight;
    });
    MeanEstimate scatter = estimateMean(kSamples, [&] {
      FreeFlight f = sampleFreeFlight(m, ray, rng, throughput);
      EXPECT_TRUE(!f.scattered || (f.t >= 0 && f.t <= 0.8f));
      return f.scattered ? f.weight : Spectrum(0);
    });
    expectAgrees(escape, t, "homogeneous escape");
    expectAgrees(scatter, scattered, "homogeneous scattering");
  }
}

// A medium that emits (pbrt-v2 regions' Le; the pbrt-v3 media do not): a slab z in [0, 1] of
// σa, σs and Le per unit length, uniform, but answering as heterogeneous so that delta tracking
// collects the emission at its tentative collisions.
class EmittingSlab : public Medium {
 public:
  EmittingSlab(Spectrum sigmaA, Spectrum sigmaS, Spectrum le, Float majorantScale)
      : sigmaA_(sigmaA), sigmaS_(sigmaS), le_(le), majorantScale_(majorantScale) {}
  Bounds3f worldBound() const override {
    return Bounds3f(Point3f(-1e3f, -1e3f, 0), Point3f(1e3f, 1e3f, 1));
  }
  bool intersectP(const Ray& ray, Float* t0, Float* t1) const override {
    if (ray.d.z == 0) return false;
    Float a = (0 - ray.o.z) / ray.d.z, b = (1 - ray.o.z) / ray.d.z;
    *t0 = std::max(Float(0), std::min(a, b));
    *t1 = std::min(ray.tMax, std::max(a, b));
    return *t0 < *t1;
  }
  MediumPoint at(const Point3f& p, Float) const override {
    if (p.z < 0 || p.z > 1) return {Spectrum(0), Spectrum(0), Spectrum(0)};
    return {sigmaA_, sigmaS_, le_};
  }
  PhaseFunction phase(const Point3f&, Float) const override { return {}; }
  Spectrum majorant(const Ray&, Float, Float) const override {
    return (sigmaA_ + sigmaS_) * majorantScale_;
  }
  bool emits() const override { return true; }

 private:
  Spectrum sigmaA_, sigmaS_, le_;
  Float majorantScale_;
};

TEST(Tracking, DeltaTrackingCollectsEmission) {
  // Radiance reaching the ray's origin from the slab's own emission, with nothing behind it and
  // the scattered part left out: ∫ T(s) Le ds = Le (1 - exp(-σt d)) / σt over the path length d.
  // Checked with a loose majorant (twice σt) and with σt = 0, where the emission is all of it.
  RNG rng(5);
  Ray ray(Point3f(0, 0, -1), normalize(Vector3f(0.3f, 0, 1)));
  Float d = 1 / ray.d.z;
  for (Spectrum sigmaT : {Spectrum(0.5f, 1, 2), Spectrum(0)}) {
    EmittingSlab slab(sigmaT * 0.5f, sigmaT * 0.5f, Spectrum(0.3f, 0.6f, 0.9f), 2);
    Spectrum expected;
    for (int c = 0; c < 3; ++c)
      expected[c] = sigmaT[c] == 0
                        ? Float(0.3f * (c + 1) * d)
                        : Float(0.3f * (c + 1) * (1 - std::exp(-sigmaT[c] * d)) / sigmaT[c]);
    MeanEstimate m =
        estimateMean(kSamples, [&] { return sampleFreeFlight(slab, ray, rng).emitted; });
    expectAgrees(m, expected, "emission");
  }
}

}  // namespace
}  // namespace candela
