// The irradiance cache's parts: the octree finds every sample whose sphere holds the point, the
// interpolation weights follow pbrt 2e §15.5.2 with the angle in degrees, the radius follows its
// rules, and an estimate at the centre of the furnace sphere is exact.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "integrators/irradiance/irradiance_estimate.h"
#include "integrators/irradiance/irradiance_interpolation.h"
#include "support/random_geometry.h"
#include "support/render_scene.h"

namespace candela {
namespace {

TEST(IrradianceOctree, LookupVisitsEverySampleWhoseSphereHoldsThePoint) {
  RNG rng(3);
  IrradianceOctree tree(Bounds3f(Point3f(-1, -1, -1), Point3f(1, 1, 1)));
  for (int i = 0; i < 2000; ++i) {
    // Radii over three decades, so that samples land at many depths.
    Float radius = 0.002f * std::pow(500.f, rng.uniformFloat());
    tree.add({test::randomPoint(rng, -1, 1), Normal3f(0, 0, 1), Spectrum(Float(i)), radius});
  }
  for (int q = 0; q < 500; ++q) {
    Point3f p = test::randomPoint(rng, -1, 1);
    std::set<int> visited;
    int visits = 0;
    tree.forEachNear(p, [&](const IrradianceSample& s) {
      visited.insert(int(s.E[0]));
      ++visits;
    });
    EXPECT_EQ(visits, int(visited.size())) << "a sample was visited twice";
    for (size_t i = 0; i < tree.size(); ++i) {
      const IrradianceSample& s = tree.samples()[i];
      if (distance(p, s.p) < s.radius) {
        EXPECT_TRUE(visited.count(int(i))) << "sample " << i;
      }
    }
  }
  EXPECT_GT(tree.memoryBytes(), tree.size() * sizeof(IrradianceSample));
}

TEST(IrradianceInterpolation, WeightIsOneMinusTheLargerError) {
  IrradianceSample s{Point3f(0, 0, 0), Normal3f(0, 0, 1), Spectrum(1), 2};
  const Float cosMax = std::cos(radians(10));
  // Position error only: distance over radius.
  EXPECT_FLOAT_EQ(interpolationWeight(s, Point3f(1, 0, 0), Normal3f(0, 0, 1), cosMax), 0.5f);
  EXPECT_FLOAT_EQ(interpolationWeight(s, Point3f(0, 0.5f, 0), Normal3f(0, 0, 1), cosMax), 0.75f);
  EXPECT_EQ(interpolationWeight(s, Point3f(2.01f, 0, 0), Normal3f(0, 0, 1), cosMax), 0);
  // Normal error only: sqrt((1 - cos) / (1 - cos max)); 0 at the largest angle and beyond.
  Float a = radians(5);
  Normal3f tilted(std::sin(a), 0, std::cos(a));
  Float expected = 1 - std::sqrt((1 - std::cos(a)) / (1 - cosMax));
  EXPECT_NEAR(interpolationWeight(s, Point3f(0, 0, 0), tilted, cosMax), expected, 1e-5);
  // The larger of the two.
  EXPECT_NEAR(interpolationWeight(s, Point3f(0, 1.8f, 0), tilted, cosMax), 0.1f, 1e-5);
  // A sample in front of the point (above its tangent plane) is not used, one behind is.
  EXPECT_EQ(interpolationWeight(s, Point3f(0.5f, 0, -0.5f), Normal3f(0, 0, 1), cosMax), 0);
  EXPECT_GT(interpolationWeight(s, Point3f(0.5f, 0, 0.5f), Normal3f(0, 0, 1), cosMax), 0);
}

// maxangledifference is in degrees: 10 means 10 degrees, not the 68 that pbrt-v2's
// cos(Degrees(10)) made of it.
TEST(IrradianceInterpolation, MaxAngleDifferenceIsInDegrees) {
  IrradianceSample s{Point3f(0, 0, 0), Normal3f(0, 0, 1), Spectrum(1), 1};
  const Float cosMax = std::cos(radians(10));
  for (Float degrees : {9.f, 11.f, 30.f, 60.f}) {
    Float a = radians(degrees);
    Float w =
        interpolationWeight(s, Point3f(0, 0, 0), Normal3f(std::sin(a), 0, std::cos(a)), cosMax);
    if (degrees < 10)
      EXPECT_GT(w, 0) << degrees;
    else
      EXPECT_EQ(w, 0) << degrees;
  }
}

TEST(IrradianceInterpolation, AverageIsWeightedAndNeedsMinWeight) {
  IrradianceOctree tree(Bounds3f(Point3f(-2, -2, -2), Point3f(2, 2, 2)));
  tree.add({Point3f(0, 0, 0), Normal3f(0, 0, 1), Spectrum(1), 1});
  tree.add({Point3f(1, 0, 0), Normal3f(0, 0, 1), Spectrum(3), 1});
  // At x = 0.25: weights 0.75 and 0.25.
  InterpolatedIrradiance r =
      interpolateIrradiance(tree, Point3f(0.25f, 0, 0), Normal3f(0, 0, 1), std::cos(radians(10)));
  EXPECT_FLOAT_EQ(r.sumWeight, 1);
  EXPECT_FLOAT_EQ(r.E()[0], 0.75f * 1 + 0.25f * 3);
  EXPECT_TRUE(r.acceptable(1));
  EXPECT_FALSE(r.acceptable(1.01f));
  InterpolatedIrradiance none =
      interpolateIrradiance(tree, Point3f(0, 1.5f, 0), Normal3f(0, 0, 1), std::cos(radians(10)));
  EXPECT_FALSE(none.acceptable(0));
}

TEST(IrradianceEstimate, RadiusIsMaxErrorTimesHarmonicMeanCappedAndClamped) {
  IrradianceCacheSettings s;
  s.maxError = 0.5f;
  s.minPixelSpacing = 2;
  s.maxPixelSpacing = 10;
  IrradianceEstimate e;
  e.harmonicMeanDistance = 4;
  e.minHitDistance = 10;
  EXPECT_FLOAT_EQ(validityRadius(e, 0.1f, s, 100), 1);  // 0.5 * 4 = 2, clamped to [0.2, 1]
  EXPECT_FLOAT_EQ(validityRadius(e, 1, s, 100), 2);     // inside [2, 10]
  e.minHitDistance = 2;                                 // half the nearest hit caps it at 1
  EXPECT_FLOAT_EQ(validityRadius(e, 0.25f, s, 100), 1);
  EXPECT_FLOAT_EQ(validityRadius(e, 1, s, 100), 2);  // then the pixel clamp raises it
  EXPECT_FLOAT_EQ(validityRadius(e, 0, s, 100), 1);  // no pixel size: no clamp
  e.harmonicMeanDistance = e.minHitDistance = kInfinity;
  EXPECT_FLOAT_EQ(validityRadius(e, 0, s, 100), 100);  // nothing hit: the scene's size
}

// At the centre of the furnace sphere (radius 1, albedo rho, emitting Le) with paths of one
// bounce, every ray meets the wall at distance 1 and carries exactly rho Le (the wall's direct
// light, whose estimators have no variance inside a sphere; its own emission is left out), so
// E = pi rho Le and both distances are 1, to rounding.
TEST(IrradianceEstimate, CentreOfTheFurnaceIsExact) {
  auto built = test::buildSceneText(
      "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"perspective\"\nWorldBegin\n"
      "Material \"matte\" \"rgb Kd\" [0.5 0.5 0.5]\n"
      "AreaLightSource \"diffuse\" \"rgb L\" [0.25 0.25 0.25]\n"
      "ReverseOrientation\nShape \"sphere\" \"float radius\" [1]\nWorldEnd\n");
  const Scene& scene = *built.job().scene;
  PathIntegrator paths(1);
  for (Normal3f n : {Normal3f(0, 0, 1), Normal3f(0.6f, 0, -0.8f)}) {
    IrradianceQuery q{Interaction(Point3f(0, 0, 0), n, Vector3f(0, 0, 0), Vector3f(n), 0), n, 0};
    RayStats stats;
    for (int nFilter : {0, 4}) {
      IrradianceEstimate e = estimateIrradiance(q, scene, paths, 64, nFilter, 9, stats);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(e.E[c], kPi * 0.5f * 0.25f, 1e-5);
      EXPECT_NEAR(e.harmonicMeanDistance, 1, 1e-5);
      EXPECT_NEAR(e.minHitDistance, 1, 1e-5);
    }
    EXPECT_GT(stats.intersectionRays, 0u);
  }
}

}  // namespace
}  // namespace candela
