// The light samplers of lightsamplestrategy (lights/light_sampler.h): each one's probabilities
// sum to 1 and agree with what sample() returns; power follows the lights' power; spatial
// prefers the light near the point, keeps every light possible, and gives the same
// probabilities whichever order its voxels are made in.
#include <gtest/gtest.h>

#include <cmath>
#include <thread>

#include "lights/light_sampler.h"
#include "lights/spatial_light_sampler.h"
#include "support/render_scene.h"

namespace candela {
namespace {

// Point lights of intensity I at x = positions, in a scene whose bounds are given by a ground
// quad: built through the scene reader, as the integrator sees them.
std::string pointLightsScene(const std::vector<std::pair<Float, Float>>& xAndIntensity) {
  std::string s =
      "LookAt 0 5 5 0 0 0 0 1 0\nCamera \"perspective\"\n"
      "Film \"image\" \"integer xresolution\" [4] \"integer yresolution\" [4]\n"
      "Integrator \"path\"\nWorldBegin\n";
  for (auto [x, i] : xAndIntensity)
    s += "LightSource \"point\" \"point from\" [" + std::to_string(x) + " 1 0] \"rgb I\" [" +
         std::to_string(i) + " " + std::to_string(i) + " " + std::to_string(i) + "]\n";
  s += "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3] \"point P\" "
       "[-20 0 -20 20 0 -20 20 0 20 -20 0 20]\nWorldEnd\n";
  return s;
}

void expectConsistent(const LightSampler& sampler, const Scene& scene, const Point3f& p) {
  Float sum = 0;
  for (const Light* l : scene.lights()) sum += sampler.pmf(p, *l);
  EXPECT_NEAR(sum, 1, 1e-5);
  for (Float u = 0.005f; u < 1; u += 0.01f) {
    Float pmf = 0;
    const Light* l = sampler.sample(p, u, &pmf);
    ASSERT_NE(l, nullptr);
    EXPECT_GT(pmf, 0);
    EXPECT_EQ(pmf, sampler.pmf(p, *l)) << u;
  }
}

TEST(LightSampler, StrategiesByName) {
  EXPECT_EQ(lightSampleStrategyNamed("uniform"), LightSampleStrategy::Uniform);
  EXPECT_EQ(lightSampleStrategyNamed("power"), LightSampleStrategy::Power);
  EXPECT_EQ(lightSampleStrategyNamed("spatial"), LightSampleStrategy::Spatial);
  EXPECT_EQ(lightSampleStrategyNamed("bvh"), LightSampleStrategy::Bvh);
  EXPECT_EQ(lightSampleStrategyNamed("tree"), std::nullopt);
}

TEST(LightSampler, UniformAndPowerProbabilities) {
  auto built = test::buildSceneText(pointLightsScene({{-5, 1}, {0, 3}, {5, 12}}));
  const Scene& scene = *built.job().scene;
  Point3f p(1, 0, 2);
  auto uniform =
      createLightSampler(LightSampleStrategy::Uniform, scene.lights(), scene.worldBound());
  auto power = createLightSampler(LightSampleStrategy::Power, scene.lights(), scene.worldBound());
  for (const Light* l : scene.lights()) EXPECT_FLOAT_EQ(uniform->pmf(p, *l), 1.0f / 3);
  // Power 4 pi I: in proportion 1 : 3 : 12.
  EXPECT_NEAR(power->pmf(p, *scene.lights()[0]), 1.0 / 16, 1e-6);
  EXPECT_NEAR(power->pmf(p, *scene.lights()[1]), 3.0 / 16, 1e-6);
  EXPECT_NEAR(power->pmf(p, *scene.lights()[2]), 12.0 / 16, 1e-6);
  expectConsistent(*uniform, scene, p);
  expectConsistent(*power, scene, p);
}

TEST(LightSampler, PowerOfLightsWithoutPowerIsUniform) {
  auto built = test::buildSceneText(pointLightsScene({{-5, 0}, {5, 0}}));
  const Scene& scene = *built.job().scene;
  auto power = createLightSampler(LightSampleStrategy::Power, scene.lights(), scene.worldBound());
  for (const Light* l : scene.lights()) EXPECT_FLOAT_EQ(power->pmf(Point3f(), *l), 0.5f);
}

TEST(LightSampler, SpatialPrefersTheNearLightAndKeepsTheFarOnePossible) {
  auto built = test::buildSceneText(pointLightsScene({{-15, 1}, {15, 1}}));
  const Scene& scene = *built.job().scene;
  SpatialLightSampler spatial(scene.lights(), scene.worldBound());
  EXPECT_EQ(spatial.voxels(0), 64);  // the longest axes, x and z
  EXPECT_EQ(spatial.voxels(2), 64);
  EXPECT_GE(spatial.voxels(1), 1);
  const Light& left = *scene.lights()[0];
  const Light& right = *scene.lights()[1];
  Point3f nearLeft(-15, 0.5f, 0), middle(0.1f, 0.5f, 0);
  // Irradiance from a point light falls as 1 / d^2: about 0.25 from the left light at the
  // voxel under it against (1 / 30)^2 from the right one.
  EXPECT_GT(spatial.pmf(nearLeft, left), 0.99f);
  EXPECT_GT(spatial.pmf(nearLeft, right), 0);
  // The voxel holding the middle point lies just right of the centre, nearer the right light.
  EXPECT_GT(spatial.pmf(middle, left), 0.45f);
  EXPECT_LT(spatial.pmf(middle, left), 0.5f);
  expectConsistent(spatial, scene, nearLeft);
  expectConsistent(spatial, scene, middle);
  // Points outside the bounds (and NaN) fall in the nearest voxel.
  EXPECT_EQ(spatial.pmf(Point3f(-1e30f, 0.5f, 0), left), spatial.pmf(Point3f(-20, 0.5f, 0), left));
  EXPECT_GT(spatial.pmf(Point3f(NAN, 0, 0), left), 0);
}

TEST(LightSampler, SpatialGivesALightThatReachesNoSampledPointAThousandthOfTheMean) {
  // A spot light pointing up lights none of the ground's voxels.
  std::string text = pointLightsScene({{-15, 1}, {15, 1}});
  text.insert(text.find("WorldBegin\n") + 11,
              "LightSource \"spot\" \"point from\" [0 1 0] \"point to\" [0 2 0] "
              "\"float coneangle\" [30] \"rgb I\" [5 5 5]\n");
  auto built = test::buildSceneText(text);
  const Scene& scene = *built.job().scene;
  SpatialLightSampler spatial(scene.lights(), scene.worldBound());
  const Light& spot = *scene.lights()[0];
  for (Point3f p : {Point3f(-15, 0, 0), Point3f(0.1f, 0, 0), Point3f(15, 0, 3)}) {
    const Distribution1D& d = spatial.distributionAt(p);
    // Its weight is a thousandth of the mean of one light at one of the voxel's 128 points.
    Float floor = 0.001f * (d.func(1) + d.func(2)) / (128 * 3);
    EXPECT_NEAR(d.func(0), floor, 1e-5f * floor);
    EXPECT_GT(spatial.pmf(p, spot), 0);
    EXPECT_LT(spatial.pmf(p, spot), 0.001f);
  }
}

TEST(LightSampler, SpatialProbabilitiesAreTheSameMadeFromTwoThreads) {
  auto built = test::buildSceneText(pointLightsScene({{-15, 1}, {-3, 2}, {4, 0.5f}, {15, 1}}));
  const Scene& scene = *built.job().scene;
  std::vector<Point3f> points;
  for (int i = 0; i < 400; ++i)
    points.emplace_back(-20 + 0.1f * Float(i), 0.5f + 0.001f * Float(i), 7 - 0.035f * Float(i));
  // One sampler asked in order from one thread; the other from two threads at once, from both
  // ends.
  SpatialLightSampler one(scene.lights(), scene.worldBound());
  SpatialLightSampler two(scene.lights(), scene.worldBound());
  std::thread a([&] {
    for (const Point3f& p : points) two.distributionAt(p);
  });
  std::thread b([&] {
    for (size_t i = points.size(); i-- > 0;) two.distributionAt(points[i]);
  });
  a.join();
  b.join();
  for (const Point3f& p : points)
    for (const Light* l : scene.lights()) ASSERT_EQ(one.pmf(p, *l), two.pmf(p, *l));
}

// The image is the same bits whichever thread makes a voxel's distribution first.
TEST(LightSampler, SpatialRendersTheSameBitsOnOneAndTwoThreads) {
  std::string text = pointLightsScene({{-15, 1}, {-3, 2}, {4, 0.5f}, {15, 1}});
  auto replace = [&](const std::string& from, const std::string& to) {
    text.replace(text.find(from), from.size(), to);
  };
  replace("Integrator \"path\"",
          "Sampler \"random\" \"integer pixelsamples\" [4]\nIntegrator \"path\" "
          "\"string lightsamplestrategy\" \"spatial\" \"integer maxdepth\" [3]");
  replace("[4] \"integer yresolution\" [4]", "[24] \"integer yresolution\" [16]");
  std::vector<std::vector<float>> images;
  for (auto [threads, tile] : {std::pair{1, 16}, std::pair{2, 4}, std::pair{2, 7}}) {
    test::TestRenderOptions o;
    o.render.nThreads = threads;
    o.render.tileSize = tile;
    images.push_back(test::renderSceneText(text, o).film().image().data);
  }
  double sum = 0;
  for (float v : images[0]) sum += v;
  EXPECT_GT(sum, 0);
  EXPECT_EQ(images[0], images[1]);
  EXPECT_EQ(images[0], images[2]);
}

}  // namespace
}  // namespace candela
