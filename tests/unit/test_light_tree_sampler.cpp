// The light tree ("bvh", lights/light_tree_sampler.h) and what it is built from: each point's
// probabilities sum to 1 and are what sample() returns, to the bit; the fraction of u in [0, 1)
// that picks each light is its probability; a light the tree never picks at a point sends it
// nothing; lights at infinity share with the tree; the cone and bounds helpers hold what they
// bound; degenerate sets of lights make a tree of bounded depth.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <typeinfo>

#include "core/direction_cone.h"
#include "lights/light_bounds.h"
#include "lights/light_tree_sampler.h"
#include "shapes/triangle_mesh.h"
#include "support/render_scene.h"

namespace candela {
namespace {

std::string num(double v) { return std::to_string(v); }

// A scene of many lights for the tree: small one-sided triangles facing every way, two-sided ones,
// point lights, spot lights and (when asked) a distant light, over a ground quad.
std::string manyLightsScene(int triangles, bool distant, uint32_t seed = 7) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::string s =
      "LookAt 0 5 5 0 0 0 0 1 0\nCamera \"perspective\"\n"
      "Film \"image\" \"integer xresolution\" [4] \"integer yresolution\" [4]\n"
      "Integrator \"path\"\nWorldBegin\n";
  if (distant)
    s += "LightSource \"distant\" \"point from\" [0 1 0] \"point to\" [0 0 0] \"rgb L\" [2 2 2]\n";
  for (int i = 0; i < triangles; ++i) {
    double x = -10 + 20 * u(rng), y = 0.5 + 4 * u(rng), z = -10 + 20 * u(rng), e = 0.2 + u(rng);
    auto corner = [&] {
      return num(x + 0.6 * (u(rng) - 0.5)) + " " + num(y + 0.6 * (u(rng) - 0.5)) + " " +
             num(z + 0.6 * (u(rng) - 0.5)) + " ";
    };
    s += "AttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [" + num(e) + " " + num(e) + " " +
         num(e) + "]" + (i % 5 == 0 ? " \"bool twosided\" true" : "") +
         "\nShape \"trianglemesh\" \"integer indices\" [0 1 2] \"point P\" [" + corner() +
         corner() + corner() + "]\nAttributeEnd\n";
  }
  for (int i = 0; i < 6; ++i)
    s += "LightSource \"point\" \"point from\" [" + num(-8 + 3 * i) + " 2 " + num(3 - i) +
         "] \"rgb I\" [" + num(1 + i) + " 1 1]\n";
  s += "LightSource \"spot\" \"point from\" [0 3 0] \"point to\" [0 0 0] \"float coneangle\" [20] "
       "\"float conedelta\" [5] \"rgb I\" [9 9 9]\n"
       "LightSource \"spot\" \"point from\" [5 3 5] \"point to\" [5 6 5] \"float coneangle\" [30] "
       "\"float conedelta\" [0] \"rgb I\" [9 9 9]\n";
  s += "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point P\" "
       "[-20 0 -20 20 0 -20 20 0 20 -20 0 20]\nWorldEnd\n";
  return s;
}

std::vector<LightSampleContext> someContexts() {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-1, 1);
  std::vector<LightSampleContext> at;
  for (int i = 0; i < 40; ++i) {
    Point3f p(12 * u(rng), 3 + 3 * u(rng), 12 * u(rng));
    Vector3f n(u(rng), u(rng), u(rng));
    // Every fourth in a medium (no normal), the rest on surfaces facing anywhere.
    at.emplace_back(p, i % 4 == 0 ? Normal3f() : Normal3f(normalize(n)));
  }
  at.emplace_back(Point3f(0, 0, 0), Normal3f(0, 1, 0));  // on the ground
  // Just under the spot light. (At its very position its importance is the largest Float and
  // every other light's probability underflows.)
  at.emplace_back(Point3f(0, 2.99f, 0), Normal3f(0, 1, 0));
  return at;
}

TEST(LightTreeSampler, ProbabilitiesSumToOneAndAreWhatSampleReturns) {
  auto built = test::buildSceneText(manyLightsScene(300, true));
  const Scene& scene = *built.job().scene;
  LightTreeSampler tree(scene.lights());
  EXPECT_EQ(tree.lightsAtInfinity(), 1);
  EXPECT_EQ(tree.nodeCount(), 2 * (300 + 6 + 2) - 1);
  const Light* distant = nullptr;
  for (const Light* l : scene.lights())
    if (l->atInfinity()) distant = l;
  ASSERT_NE(distant, nullptr);
  for (const LightSampleContext& at : someContexts()) {
    // One light at infinity: it and the tree take half each.
    EXPECT_EQ(tree.pmf(at, *distant), 0.5f);
    // Stratified u: the fraction of values picking each light is its probability, within the
    // rounding of a descent of depth() choices over n values. The rest pick none: a node whose
    // children can both be ruled out though it could not (the probabilities then sum to less
    // than 1, by what no light could have sent).
    const int n = 20000;
    std::map<const Light*, int> picked;
    int none = 0;
    for (int i = 0; i < n; ++i) {
      Float pmf = 0;
      const Light* l = tree.sample(at, (Float(i) + 0.5f) / Float(n), &pmf);
      if (!l) {
        ASSERT_EQ(pmf, 0);
        ++none;
        continue;
      }
      ASSERT_GT(pmf, 0);
      ASSERT_EQ(pmf, tree.pmf(at, *l));
      ++picked[l];
    }
    double sum = 0;
    for (const Light* l : scene.lights()) {
      sum += tree.pmf(at, *l);
      EXPECT_NEAR(double(picked[l]) / n, tree.pmf(at, *l), 2.0 * tree.depth() / n);
    }
    EXPECT_NEAR(sum + double(none) / n, 1, 2.0 * tree.depth() / n);
  }
}

// A light with probability 0 at a point sends it no light: sampled many times, its radiance times
// the cosine at the point is 0 every time. And the tree does give 0 to lights that cannot reach.
TEST(LightTreeSampler, OnlyLightsThatCannotReachThePointHaveProbabilityZero) {
  auto built = test::buildSceneText(manyLightsScene(300, false));
  const Scene& scene = *built.job().scene;
  LightTreeSampler tree(scene.lights());
  int zero = 0;
  for (const LightSampleContext& at : someContexts()) {
    Interaction ref(at.p, at.n, Vector3f(), Vector3f(0, 0, 1), 0);
    for (const Light* l : scene.lights()) {
      if (tree.pmf(at, *l) > 0) continue;
      ++zero;
      for (int i = 0; i < 64; ++i) {
        Point2f u((Float(i % 8) + 0.5f) / 8, (Float(i / 8) + 0.5f) / 8);
        Vector3f wi;
        Float pdf = 0;
        VisibilityTester vis;
        Spectrum li = l->sampleLi(ref, u, &wi, &pdf, &vis);
        Float cosine = at.n == Normal3f() ? 1 : absDot(wi, at.n);
        ASSERT_TRUE(pdf == 0 || li.isBlack() || cosine == 0)
            << "a light the tree never picks (" << typeid(*l).name() << ", power " << l->power().y()
            << ") lights (" << at.p.x << ", " << at.p.y << ", " << at.p.z << ")";
      }
    }
  }
  // One-sided triangles facing away and the upward spot give many zeros.
  EXPECT_GT(zero, 1000);
}

TEST(LightTreeSampler, TheSpotsConeDecidesWhetherItCanBePicked) {
  std::string text =
      "LookAt 0 5 5 0 0 0 0 1 0\nCamera \"perspective\"\n"
      "Film \"image\" \"integer xresolution\" [4] \"integer yresolution\" [4]\nWorldBegin\n"
      "LightSource \"spot\" \"point from\" [0 4 0] \"point to\" [0 0 0] \"float coneangle\" [20] "
      "\"float conedelta\" [0] \"rgb I\" [9 9 9]\n"
      "LightSource \"point\" \"point from\" [30 4 0] \"rgb I\" [1 1 1]\n"
      "Shape \"sphere\"\nWorldEnd\n";
  auto built = test::buildSceneText(text);
  const Scene& scene = *built.job().scene;
  LightTreeSampler tree(scene.lights());
  const Light& spot = *scene.lights()[0];
  // tan 20° × 4 = 1.46: inside the hard-edged cone, and well outside it.
  EXPECT_GT(tree.pmf(LightSampleContext(Point3f(0.5f, 0, 0)), spot), 0.9f);
  EXPECT_GT(tree.pmf(LightSampleContext(Point3f(1.3f, 0, 0)), spot), 0);
  EXPECT_EQ(tree.pmf(LightSampleContext(Point3f(3, 0, 0)), spot), 0);
  EXPECT_EQ(tree.pmf(LightSampleContext(Point3f(0, 5, 0)), spot), 0);  // behind it
}

TEST(LightTreeSampler, ChoosesTheNearLightAmongManyFarOnes) {
  std::string s =
      "LookAt 0 5 5 0 0 0 0 1 0\nCamera \"perspective\"\n"
      "Film \"image\" \"integer xresolution\" [4] \"integer yresolution\" [4]\nWorldBegin\n";
  for (int i = 0; i < 100; ++i)
    for (int j = 0; j < 100; ++j)
      s += "LightSource \"point\" \"point from\" [" + num(i) + " 1 " + num(j) +
           "] \"rgb I\" [1 1 1]\n";
  s += "Shape \"sphere\"\nWorldEnd\n";
  auto built = test::buildSceneText(s);
  const Scene& scene = *built.job().scene;
  LightTreeSampler tree(scene.lights());
  // Under light (40, 1, 60), 0.1 below it: its irradiance is 100 times that of its nearest
  // neighbours, and the rest of the 10,000 together send about as much as the neighbours.
  LightSampleContext at(Point3f(40, 0.9f, 60), Normal3f(0, 1, 0));
  // Measured 0.072 (power: 1e-4; by irradiance it would be about 0.8): the upper nodes are wide
  // and tell near from far only roughly.
  EXPECT_GT(tree.pmf(at, *scene.lights()[40 * 100 + 60]), 0.05f);
  EXPECT_LT(tree.depth(), 40);
}

TEST(LightTreeSampler, LightsInOnePlaceMakeATreeOfBoundedDepth) {
  std::string s =
      "LookAt 0 5 5 0 0 0 0 1 0\nCamera \"perspective\"\n"
      "Film \"image\" \"integer xresolution\" [4] \"integer yresolution\" [4]\nWorldBegin\n";
  for (int i = 0; i < 3000; ++i)
    s += "LightSource \"point\" \"point from\" [1 2 3] \"rgb I\" [" + num(1 + i % 7) + " 1 1]\n";
  // And lights at distances doubling each time, which a cost-driven split peels one by one.
  for (int i = 0; i < 100; ++i)
    s += "LightSource \"point\" \"point from\" [" + num(std::ldexp(1.0, i / 4)) + " 0 0]\n";
  s += "Shape \"sphere\"\nWorldEnd\n";
  auto built = test::buildSceneText(s);
  const Scene& scene = *built.job().scene;
  LightTreeSampler tree(scene.lights());
  EXPECT_LE(tree.depth(), 64 + 13);
  LightSampleContext at(Point3f(0, 0, 0));
  double sum = 0;
  for (const Light* l : scene.lights()) sum += tree.pmf(at, *l);
  EXPECT_NEAR(sum, 1, 1e-5);
  // The same lights make the same tree.
  LightTreeSampler again(scene.lights());
  for (const Light* l : scene.lights()) ASSERT_EQ(tree.pmf(at, *l), again.pmf(at, *l));
}

TEST(LightTreeSampler, NoLightsOrOnlyLightsAtInfinity) {
  std::vector<const Light*> none;
  LightTreeSampler empty(none);
  Float pmf = 1;
  EXPECT_EQ(empty.sample(LightSampleContext(Point3f()), 0.3f, &pmf), nullptr);
  EXPECT_EQ(pmf, 0);
  auto built = test::buildSceneText(
      "LookAt 0 5 5 0 0 0 0 1 0\nCamera \"perspective\"\nWorldBegin\n"
      "LightSource \"distant\" \"point to\" [0 -1 0]\nLightSource \"infinite\"\n"
      "Shape \"sphere\"\nWorldEnd\n");
  const Scene& scene = *built.job().scene;
  LightTreeSampler sky(scene.lights());
  for (Float u : {0.0f, 0.49f, 0.5f, 0.99f, kOneMinusEpsilon}) {
    const Light* l = sky.sample(LightSampleContext(Point3f()), u, &pmf);
    ASSERT_NE(l, nullptr);
    EXPECT_EQ(pmf, 0.5f);
    EXPECT_EQ(l, scene.lights()[u < 0.5f ? 0 : 1]);
  }
}

// Every direction of both cones lies in their union: their axes' far edges are within its angle.
TEST(DirectionCone, UnionHoldsBothCones) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-1, 1);
  auto randomCone = [&] {
    Vector3f w(u(rng), u(rng), u(rng));
    return DirectionCone{normalize(w), u(rng)};
  };
  for (int i = 0; i < 2000; ++i) {
    DirectionCone a = randomCone(), b = randomCone();
    DirectionCone c = unionOf(a, b);
    if (c.coversEveryDirection()) continue;
    // Angles in double, between directions by atan2, so that the check's own rounding is far
    // below the union's widening of 1e-3.
    auto angle = [](const Vector3f& x, const Vector3f& y) {
      double cx = double(x.y) * y.z - double(x.z) * y.y, cy = double(x.z) * y.x - double(x.x) * y.z,
             cz = double(x.x) * y.y - double(x.y) * y.x;
      double d = double(x.x) * y.x + double(x.y) * y.y + double(x.z) * y.z;
      return std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), d);
    };
    auto halfAngle = [](const DirectionCone& k) { return std::acos(double(k.cosTheta)); };
    for (const DirectionCone& part : {a, b})
      ASSERT_LE(angle(c.w, part.w) + halfAngle(part), halfAngle(c) + 1e-6);
    // And it is no wider than it needs to be: half of both cones' span (or the wider cone).
    double span = halfAngle(a) + angle(a.w, b.w) + halfAngle(b);
    EXPECT_LE(halfAngle(c), std::max(span / 2, std::max(halfAngle(a), halfAngle(b))) + 1.1e-3);
  }
  DirectionCone up = DirectionCone::of(Vector3f(0, 0, 1));
  EXPECT_TRUE(unionOf(up, DirectionCone::of(Vector3f(0, 0, -1))).coversEveryDirection());
  DirectionCone both = unionOf(up, DirectionCone::of(Vector3f(1, 0, 0)));
  EXPECT_NEAR(both.cosTheta, std::cos(kPi / 4 + 1e-3f), 1e-6);
  EXPECT_NEAR(both.w.x, std::sqrt(0.5f), 1e-6);
  EXPECT_NEAR(both.w.z, std::sqrt(0.5f), 1e-6);
}

TEST(LightBounds, WorldConeOfARotationIsExactAndOfAnUnevenScaleIsEverything) {
  DirectionCone turned = worldConeOfLightZ(rotate(90, Vector3f(1, 0, 0)) * scale(2, 2, 2), 0.5f);
  EXPECT_NEAR(turned.w.y, -1, 1e-6);
  EXPECT_EQ(turned.cosTheta, 0.5f);
  EXPECT_TRUE(worldConeOfLightZ(scale(1, 1, 3), 0.5f).coversEveryDirection());
}

TEST(LightBounds, ImportanceIsZeroBehindAOneSidedEmitterAndFiniteAtAPoint) {
  LightBounds b;
  b.bounds = Bounds3f(Point3f(-1, -1, 0), Point3f(1, 1, 0));
  b.phi = 1;
  b.w = Vector3f(0, 0, 1);
  b.cosThetaO = 1;
  EXPECT_GT(b.importance(Point3f(5, 0, 0.1f), Normal3f()), 0);  // just in front, far to the side
  // Behind, where the bounds' sphere seen from the point (14° wide) does not reach 90° from w.
  EXPECT_EQ(b.importance(Point3f(5, 0, -3), Normal3f()), 0);
  EXPECT_EQ(b.importance(Point3f(0, 0, -3), Normal3f(0, 0, 1)), 0);
  // Just behind, the sphere reaches past the plane: the bound cannot rule it out.
  EXPECT_GT(b.importance(Point3f(5, 0, -0.1f), Normal3f()), 0);
  b.twoSided = true;
  EXPECT_GT(b.importance(Point3f(0, 0, -3), Normal3f(0, 0, 1)), 0);
  LightBounds point = pointSourceBounds(Point3f(1, 2, 3), Spectrum(1e30f));
  // A receiver whose plane holds the light gets next to none of it: the sine of the bound's
  // 1e-3 margin against rounding, of what it gets facing the light.
  Float grazing = point.importance(Point3f(1, 2, 30), Normal3f(1, 0, 0));
  Float facing = point.importance(Point3f(1, 2, 30), Normal3f(0, 0, 1));
  EXPECT_GT(grazing, 0);
  EXPECT_LT(grazing, 1.01e-3f * facing);
  Float at = point.importance(Point3f(1, 2, 3), Normal3f());
  EXPECT_TRUE(std::isfinite(at));
  EXPECT_GT(at, 0);
}

// The triangle's normal cone is the side its interactions face, and the area light's bounds
// follow it.
TEST(LightBounds, TriangleNormalBoundIsTheSideItsHitsFace) {
  for (const char* extra : {"", "ReverseOrientation\n", "Scale 1 1 -1\n"}) {
    for (bool normals : {false, true}) {
      std::string text =
          std::string("LookAt 0 0 5 0 0 0 0 1 0\nCamera \"perspective\"\nWorldBegin\n") + extra +
          "Shape \"trianglemesh\" \"integer indices\" [0 1 2] \"point P\" "
          "[-1 -1 0 1 -1 0 0 1 0]" +
          (normals ? " \"normal N\" [0 0 -1 0.2 0 -1 0 0.2 -1]" : "") + "\nWorldEnd\n";
      auto built = test::buildSceneText(text);
      const Shape& shape = *built.job().shapes.at(0);
      DirectionCone cone = shape.normalBound();
      SurfaceInteraction isect;
      Float t;
      ASSERT_TRUE(shape.intersect(Ray(Point3f(0, 0, 5), Vector3f(0, 0, -1)), &t, &isect));
      EXPECT_EQ(cone.cosTheta, 1) << extra << normals;
      EXPECT_GT(dot(cone.w, isect.n), 0.999f) << extra << normals;
    }
  }
}

}  // namespace
}  // namespace candela
