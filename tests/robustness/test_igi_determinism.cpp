// "igi" keeps the image a pure function of (scene, spp, seed): its VPL sets come from numbered
// light paths, so 1 or 2 threads, tiles of 8 or 16 pixels and a crop window give the same bits.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <string>

#include "integrators/instant_global_illumination.h"
#include "support/render_scene.h"

namespace candela {
namespace {

// A room corner under an area light and a point light, with a mirror sphere (specular
// recursion) and a small glimit so that gather rays do run.
const char* kScene =
    "LookAt 0 1 -4  0 0.6 0  0 1 0\n"
    "Camera \"perspective\" \"float fov\" [55]\n"
    "Film \"image\" \"integer xresolution\" [20] \"integer yresolution\" [16]\n"
    "Sampler \"random\" \"integer pixelsamples\" [2]\n"
    "SurfaceIntegrator \"igi\" \"integer nlights\" [16] \"integer nsets\" [3]\n"
    "  \"float glimit\" [0.5] \"integer gathersamples\" [2]\n"
    "WorldBegin\n"
    "LightSource \"point\" \"point from\" [1 2 -1] \"rgb I\" [3 3 3]\n"
    "AttributeBegin\n"
    "  AreaLightSource \"diffuse\" \"rgb L\" [4 4 4]\n"
    "  Translate -0.8 2 0.5\n"
    "  Shape \"sphere\" \"float radius\" [0.2]\n"
    "AttributeEnd\n"
    "Material \"matte\" \"rgb Kd\" [0.7 0.6 0.5]\n"
    "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3  4 5 6 4 6 7]\n"
    "  \"point P\" [-3 0 -3  3 0 -3  3 0 3  -3 0 3   -3 0 1.5  3 0 1.5  3 3 1.5  -3 3 1.5]\n"
    "AttributeBegin\n"
    "  Material \"mirror\"\n"
    "  Translate 0.5 0.5 0\n"
    "  Shape \"sphere\" \"float radius\" [0.5]\n"
    "AttributeEnd\n"
    "WorldEnd\n";

ImageBuffer render(int threads, int tile, std::optional<Bounds2f> crop = std::nullopt) {
  test::TestRenderOptions o;
  o.build.seed = 11;
  o.build.cropWindow = crop;
  o.render.nThreads = threads;
  o.render.tileSize = tile;
  return test::renderSceneText(kScene, o).film().image();
}

TEST(IgiDeterminism, SameBitsForThreadsTilesAndCrop) {
  ImageBuffer reference = render(1, 16);
  for (auto [threads, tile] : {std::pair{2, 16}, std::pair{2, 8}, std::pair{1, 8}}) {
    ImageBuffer other = render(threads, tile);
    ASSERT_EQ(reference.data.size(), other.data.size());
    EXPECT_EQ(0, std::memcmp(reference.data.data(), other.data.data(),
                             reference.data.size() * sizeof(float)))
        << threads << " threads, tile " << tile;
  }
  ImageBuffer part = render(2, 8, Bounds2f(Point2f(0.25f, 0.2f), Point2f(0.75f, 0.9f)));
  ASSERT_GT(part.width, 0);
  ASSERT_GT(part.height, 0);
  for (int y = 0; y < part.height; ++y)
    for (int x = 0; x < part.width; ++x)
      for (int c = 0; c < part.channelCount(); ++c)
        ASSERT_EQ(part.at(x, y, c), reference.at(x + part.xOffset, y + part.yOffset, c))
            << "pixel " << x + part.xOffset << "," << y + part.yOffset;
  // Not a blank image: the test would pass trivially on one.
  double sum = 0;
  for (float v : reference.data) sum += v;
  EXPECT_GT(sum, 0);
}

TEST(IgiDeterminism, TheSceneExercisesGatherRays) {
  // The gather rays (a path of their own in the integrator) do run in the scene above: without
  // them it traces fewer closest-hit rays.
  auto rays = [](const std::string& text) {
    return test::renderSceneText(text).results.front().rays.intersectionRays;
  };
  std::string noGather = kScene;
  const std::string two = "\"integer gathersamples\" [2]";
  noGather.replace(noGather.find(two), two.size(), "\"integer gathersamples\" [0]");
  EXPECT_GT(rays(kScene), rays(noGather));
}

const VirtualPointLightSets& virtualLights(test::RenderedScene& r) {
  return dynamic_cast<const InstantGlobalIlluminationIntegrator&>(*r.job().integrator)
      .virtualLights();
}

// The first VPL positions of every set.
std::vector<Point3f> positions(const VirtualPointLightSets& v) {
  std::vector<Point3f> p;
  for (const auto& set : v.sets)
    for (const auto& vpl : set) p.push_back(vpl.at.p);
  return p;
}

// --seed is part of what the image is a function of: the VPL sets of two seeds are different
// light paths, and one seed gives the same sets on every build.
TEST(IgiDeterminism, TheSeedChoosesTheVirtualLights) {
  auto build = [](uint64_t seed) {
    BuildOptions o;
    o.seed = seed;
    return test::buildSceneText(kScene, o);
  };
  auto a = build(11), again = build(11), b = build(12);
  std::vector<Point3f> pa = positions(virtualLights(a)), pb = positions(virtualLights(b));
  ASSERT_GT(pa.size(), 10u);
  EXPECT_EQ(pa, positions(virtualLights(again)));
  size_t shared = 0;
  for (const Point3f& p : pa) shared += std::count(pb.begin(), pb.end(), p);
  EXPECT_LT(shared, pa.size() / 10) << "the two seeds' VPLs are mostly the same points";
}

// Light paths start at times spread over the shutter: a floor that moves from y = 0 down to
// y = -1 while the shutter is open holds VPLs at every height between, not only at its start.
TEST(IgiDeterminism, VirtualLightsSpreadOverTheShutter) {
  const char* scene =
      "LookAt 0 3 -3  0 0 0  0 1 0\n"
      "Camera \"perspective\" \"float fov\" [60] \"float shutteropen\" [0]\n"
      "  \"float shutterclose\" [1]\n"
      "Film \"image\" \"integer xresolution\" [4] \"integer yresolution\" [4]\n"
      "SurfaceIntegrator \"igi\" \"integer nlights\" [256] \"integer nsets\" [1]\n"
      "WorldBegin\n"
      "LightSource \"point\" \"point from\" [0 2 0] \"rgb I\" [4 4 4]\n"
      "Material \"matte\"\n"
      "AttributeBegin\n"
      "  ActiveTransform EndTime\n  Translate 0 -1 0\n  ActiveTransform All\n"
      "  Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3]\n"
      "    \"point P\" [-50 0 -50  50 0 -50  50 0 50  -50 0 50]\n"
      "AttributeEnd\n"
      "WorldEnd\n";
  auto r = test::buildSceneText(scene);
  std::vector<Point3f> p = positions(virtualLights(r));
  ASSERT_GT(p.size(), 64u);
  int upperHalf = 0;
  for (const Point3f& q : p) {
    ASSERT_LE(q.y, 1e-3f);
    ASSERT_GE(q.y, -1 - 1e-3f);
    upperHalf += q.y > -0.5f;
  }
  // Times uniform over [0, 1] put half the floor hits above y = -0.5 (binomial: about 128 hits,
  // the bounds about 5 standard deviations out); times all 0 would put every one at y = 0.
  EXPECT_GT(upperHalf, int(p.size()) / 4);
  EXPECT_LT(upperHalf, int(p.size()) * 3 / 4);
}

}  // namespace
}  // namespace candela
