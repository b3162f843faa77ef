// Path guiding's SD-tree (transport/directional_quadtree.h, transport/guiding_field.h): the
// cylindrical map and its inverse agree; a learned distribution's density integrates to 1 over
// the sphere and is the density its samples are drawn with (a histogram of 20,000 draws against
// it); it puts its samples where the recorded radiance was; the sums it learns from are the same
// bits whatever order the records arrive in, and so is the field after a pass; the spatial tree
// splits where records are many.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <thread>
#include <vector>

#include "core/order_independent_sum.h"
#include "transport/directional_quadtree.h"
#include "transport/guiding_field.h"

namespace candela {
namespace {

Vector3f uniformDirection(std::mt19937& rng) {
  std::uniform_real_distribution<float> u(0, 1);
  return squareToSphereCylindrical(Point2f(u(rng), u(rng)));
}

// Radiance arriving from a cone of directions about (0.6, 0, 0.8) and, dimmer, from below.
double testRadiance(const Vector3f& w) {
  Vector3f axis(0.6f, 0, 0.8f);
  if (dot(w, axis) > 0.95f) return 10;
  return w.z < -0.5f ? 0.5 : 0;
}

// A quadtree trained on testRadiance over `passes` passes of uniform directions.
DirectionalQuadtree trained(int passes, int perPass, uint32_t seed) {
  DirectionalQuadtree tree;
  std::mt19937 rng(seed);
  for (int pass = 0; pass < passes; ++pass) {
    for (int i = 0; i < perPass; ++i) {
      Vector3f w = uniformDirection(rng);
      tree.record(w, testRadiance(w) / double(kInv4Pi));
    }
    tree.finishPass();
  }
  return tree;
}

TEST(CylindricalMap, RoundTrips) {
  std::mt19937 rng(3);
  for (int i = 0; i < 1000; ++i) {
    Vector3f w = uniformDirection(rng);
    Vector3f back = squareToSphereCylindrical(sphereToSquareCylindrical(w));
    EXPECT_NEAR(back.x, w.x, 2e-4);
    EXPECT_NEAR(back.y, w.y, 2e-4);
    EXPECT_NEAR(back.z, w.z, 2e-4);
    EXPECT_NEAR(w.length(), 1, 1e-5);
  }
}

TEST(DirectionalQuadtree, UntrainedUntilEnergyIsRecorded) {
  DirectionalQuadtree tree;
  EXPECT_FALSE(tree.trained());
  tree.finishPass();
  EXPECT_FALSE(tree.trained());
  EXPECT_EQ(tree.pdf(Vector3f(0, 0, 1)), 0);
  tree.record(Vector3f(0, 0, 1), 1);
  tree.finishPass();
  EXPECT_TRUE(tree.trained());
}

TEST(DirectionalQuadtree, RefinesWhereTheEnergyIs) {
  DirectionalQuadtree tree = trained(4, 20000, 5);
  EXPECT_GT(tree.samplingNodes(), 4);
  // Most of the samples fall in the bright cone, which holds 2/3 of the energy (0.05 of the
  // sphere: uniform directions would put 5% there).
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> u(0, 1);
  int inCone = 0, n = 20000;
  for (int i = 0; i < n; ++i) {
    Float pdf;
    Vector3f w = tree.sample(Point2f(u(rng), u(rng)), &pdf);
    if (dot(w, Vector3f(0.6f, 0, 0.8f)) > 0.95f) ++inCone;
  }
  EXPECT_GT(inCone, n * 50 / 100);
}

TEST(DirectionalQuadtree, DensityIntegratesToOneAndMatchesItsSamples) {
  DirectionalQuadtree tree = trained(4, 20000, 11);
  // The integral over the sphere, on a grid of the square (the map's Jacobian is 4 pi).
  const int n = 512;
  double integral = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      Point2f p((Float(i) + 0.5f) / n, (Float(j) + 0.5f) / n);
      integral += double(tree.pdf(squareToSphereCylindrical(p))) * 4 * kPi / (double(n) * n);
    }
  EXPECT_NEAR(integral, 1, 0.01);
  // The density sample() returns is pdf() of the direction, and the draws follow it: a chi-square
  // over 16 x 16 cells of the square against the density integrated per cell (cells expecting
  // fewer than 5 pooled). 255 degrees of freedom at most: the 0.001 quantile is about 330.
  std::mt19937 rng(21);
  std::uniform_real_distribution<float> u(0, 1);
  const int cells = 16, draws = 20000;
  std::vector<double> observed(cells * cells, 0), expected(cells * cells, 0);
  for (int k = 0; k < draws; ++k) {
    Float pdf;
    Vector3f w = tree.sample(Point2f(u(rng), u(rng)), &pdf);
    EXPECT_NEAR(pdf, tree.pdf(w), 1e-3f * pdf + 1e-6f);
    Point2f p = sphereToSquareCylindrical(w);
    observed[std::min(cells - 1, int(p.y * cells)) * cells +
             std::min(cells - 1, int(p.x * cells))] += 1;
  }
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      Point2f p((Float(i) + 0.5f) / n, (Float(j) + 0.5f) / n);
      expected[(j * cells / n) * cells + i * cells / n] +=
          double(tree.pdf(squareToSphereCylindrical(p))) * 4 * kPi / (double(n) * n) * draws;
    }
  double chi2 = 0, pooledO = 0, pooledE = 0;
  int dof = -1;
  for (int c = 0; c < cells * cells; ++c) {
    if (expected[c] < 5) {
      pooledO += observed[c];
      pooledE += expected[c];
      continue;
    }
    chi2 += (observed[c] - expected[c]) * (observed[c] - expected[c]) / expected[c];
    ++dof;
  }
  if (pooledE > 0) chi2 += (pooledO - pooledE) * (pooledO - pooledE) / pooledE, ++dof;
  EXPECT_GT(dof, 10);
  EXPECT_LT(chi2, 330) << dof << " degrees of freedom";
}

TEST(OrderIndependentSum, SameBitsInAnyOrder) {
  std::mt19937 rng(4);
  std::lognormal_distribution<double> value(0, 6);
  std::vector<double> values(100000);
  for (double& v : values) v = value(rng);
  OrderIndependentSum forward, backward, threaded;
  for (double v : values) forward.add(v);
  for (size_t i = values.size(); i-- > 0;) backward.add(values[i]);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      for (size_t i = size_t(t); i < values.size(); i += 4) threaded.add(values[i]);
    });
  for (std::thread& t : threads) t.join();
  EXPECT_EQ(forward.value(), backward.value());
  EXPECT_EQ(forward.value(), threaded.value());
  // And close to the exact sum: each value loses less than 2^-40.
  long double exact = 0;
  for (double v : values) exact += (long double)std::min(v, 0x1p32);
  EXPECT_NEAR(double(exact), forward.value(), 1e-7 * double(exact));
}

TEST(GuidingField, SameFieldForAnyRecordOrderAndSplitsWhereRecordsAre) {
  auto build = [](bool reversed) {
    auto field = std::make_unique<GuidingField>(Bounds3f(Point3f(0, 0, 0), Point3f(1, 1, 1)),
                                                /*splitFactor=*/100);
    std::mt19937 rng(8);
    std::uniform_real_distribution<float> u(0, 1);
    struct Rec {
      Point3f p;
      Vector3f w;
      double v;
    };
    std::vector<Rec> recs;
    for (int pass = 0; pass < 3; ++pass) {
      recs.clear();
      for (int i = 0; i < 20000; ++i) {
        // Points crowd the corner near the origin.
        Point3f p(u(rng) * u(rng), u(rng) * u(rng), u(rng) * u(rng));
        Vector3f w = uniformDirection(rng);
        recs.push_back({p, w, testRadiance(w) * (1 + p.x)});
      }
      if (reversed) std::reverse(recs.begin(), recs.end());
      for (const Rec& r : recs) field->record(r.p, r.w, r.v);
      field->finishPass(pass);
    }
    return field;
  };
  auto a = build(false), b = build(true);
  ASSERT_EQ(a->leaves(), b->leaves());
  EXPECT_GT(a->leaves(), 8);
  std::mt19937 rng(2);
  std::uniform_real_distribution<float> u(0, 1);
  for (int i = 0; i < 2000; ++i) {
    Point3f p(u(rng), u(rng), u(rng));
    Vector3f w = uniformDirection(rng);
    EXPECT_EQ(a->at(p).pdf(w), b->at(p).pdf(w));
  }
  // Leaves near the crowded corner are smaller: a point there and one far from it fall in
  // different leaves, as do two points close together in the corner.
  EXPECT_NE(&a->at(Point3f(0.01f, 0.01f, 0.01f)), &a->at(Point3f(0.2f, 0.2f, 0.2f)));
}

}  // namespace
}  // namespace candela
