// Photon mapping's prepass and render are pure functions of (scene, spp, seed): the same photons
// and the same image bits for any thread count, tile size or crop window. Maps the scene cannot
// use are not built, maps that cannot fill give up with a warning, and sparse maps do not hang
// the final gather.
#include <gtest/gtest.h>

#include <cstring>

#include "integrators/photon_map_integrator.h"
#include "support/photon_scenes.h"
#include "support/render_scene.h"

namespace candela {
namespace {

const char* kSmallPhotonMap =
    "\"photonmap\" \"integer causticphotons\" [1000] \"integer indirectphotons\" [4000] "
    "\"float maxdist\" [0.3] \"integer finalgathersamples\" [8]";

test::RenderedScene render(const std::string& scene, int threads, int tile,
                           std::optional<Bounds2f> crop = std::nullopt, uint64_t seed = 7) {
  test::TestRenderOptions o;
  o.build.seed = seed;
  o.build.cropWindow = crop;
  o.build.nThreads = threads;
  o.render.nThreads = threads;
  o.render.tileSize = tile;
  return test::renderSceneText(scene, o);
}

const PhotonMapIntegrator& photonIntegrator(test::RenderedScene& r) {
  return dynamic_cast<const PhotonMapIntegrator&>(*r.job().integrator);
}

void expectSamePhotons(const PhotonMap& a, const PhotonMap& b) {
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(a.nPaths(), b.nPaths());
  if (a.size() > 0) {
    EXPECT_EQ(0, std::memcmp(a.photons().data(), b.photons().data(), a.size() * sizeof(Photon)));
  }
}

void expectSameBits(const ImageBuffer& a, const ImageBuffer& b) {
  ASSERT_EQ(a.data.size(), b.data.size());
  EXPECT_EQ(0, std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)));
}

TEST(PhotonMapDeterminism, SamePhotonsAndBitsForAnyThreadCountAndTileSize) {
  std::string scene = test::causticRoom(16, 2, kSmallPhotonMap);
  auto one = render(scene, 1, 16);
  auto two = render(scene, 2, 8);
  const PhotonMapIntegrator& a = photonIntegrator(one);
  const PhotonMapIntegrator& b = photonIntegrator(two);
  EXPECT_GE(a.causticMap().size(), 1000u);
  EXPECT_GE(a.indirectMap().size(), 4000u);
  expectSamePhotons(a.causticMap(), b.causticMap());
  expectSamePhotons(a.indirectMap(), b.indirectMap());
  ASSERT_EQ(a.radianceMap().size(), b.radianceMap().size());
  expectSameBits(one.film().image(), two.film().image());
  expectSameBits(one.film().image(), render(scene, 2, 16).film().image());
  expectSameBits(one.film().image(), render(scene, 1, 8).film().image());
}

TEST(PhotonMapDeterminism, CropWindowEqualsTheSameRegionOfTheFullImage) {
  std::string scene = test::causticRoom(16, 2, kSmallPhotonMap);
  ImageBuffer full = render(scene, 2, 16).film().image();
  ImageBuffer part =
      render(scene, 2, 8, Bounds2f(Point2f(0.25f, 0.4f), Point2f(0.8f, 0.9f))).film().image();
  ASSERT_GT(part.width, 0);
  EXPECT_LT(part.width, full.width);
  for (int y = 0; y < part.height; ++y)
    for (int x = 0; x < part.width; ++x)
      for (int c = 0; c < part.channelCount(); ++c)
        ASSERT_EQ(part.at(x, y, c), full.at(x + part.xOffset, y + part.yOffset, c));
}

TEST(PhotonMapDeterminism, TheSeedChangesThePhotons) {
  std::string scene = test::causticRoom(4, 1, kSmallPhotonMap);
  auto a = render(scene, 2, 16, std::nullopt, 1);
  auto b = render(scene, 2, 16, std::nullopt, 2);
  const PhotonMap& ma = photonIntegrator(a).indirectMap();
  const PhotonMap& mb = photonIntegrator(b).indirectMap();
  size_t n = std::min(ma.size(), mb.size());
  ASSERT_GT(n, 0u);
  EXPECT_NE(0, std::memcmp(ma.photons().data(), mb.photons().data(), n * sizeof(Photon)));
}

TEST(PhotonMapBuild, OnlyTheMapsTheSceneAndSettingsNeed) {
  // Matte only: no specular surface, so no caustic map however many caustic photons are asked.
  auto matte = test::buildSceneText(test::causticRoom(4, 1, kSmallPhotonMap, "\"matte\""));
  const PhotonMapIntegrator& m = photonIntegrator(matte);
  EXPECT_TRUE(m.causticMap().empty());
  EXPECT_FALSE(m.indirectMap().empty());
  EXPECT_TRUE(m.directMap().empty());  // pbrt-v2's direct photons live only in the prepass
  EXPECT_FALSE(m.radianceMap().empty());
  const auto counts = m.buildCounts();
  EXPECT_EQ(counts.count("caustic photons"), 0u);
  EXPECT_EQ(counts.at("indirect photons"), long(m.indirectMap().size()));
  EXPECT_GT(counts.at("indirect photon map KiB"), 0);
  EXPECT_NE(m.statsReport().find("indirect photons  " + std::to_string(m.indirectMap().size())),
            std::string::npos);

  // A mirror is specular: the caustic map is built.
  auto mirror = test::buildSceneText(test::causticRoom(4, 1, kSmallPhotonMap, "\"mirror\""));
  EXPECT_FALSE(photonIntegrator(mirror).causticMap().empty());
  EXPECT_GT(photonIntegrator(mirror).buildCounts().at("caustic photons"), 0);
  // uber is specular only with a mirror term or some transparency.
  auto uber = test::buildSceneText(test::causticRoom(4, 1, kSmallPhotonMap, "\"uber\""));
  EXPECT_TRUE(photonIntegrator(uber).causticMap().empty());
  auto uberKr = test::buildSceneText(
      test::causticRoom(4, 1, kSmallPhotonMap, "\"uber\" \"rgb Kr\" [0.5 0.5 0.5]"));
  EXPECT_FALSE(photonIntegrator(uberKr).causticMap().empty());

  // No final gather: no radiance photons; direct photons only for directwithphotons.
  auto plain = test::buildSceneText(
      test::causticRoom(4, 1,
                        std::string(kSmallPhotonMap) +
                            " \"bool finalgather\" \"false\" \"integer causticphotons\" [0]"));
  EXPECT_TRUE(photonIntegrator(plain).radianceMap().empty());
  EXPECT_TRUE(photonIntegrator(plain).causticMap().empty());
  EXPECT_TRUE(photonIntegrator(plain).directMap().empty());
  auto direct = test::buildSceneText(test::causticRoom(
      4, 1,
      std::string(kSmallPhotonMap) +
          " \"bool directwithphotons\" \"true\" \"integer directphotons\" [2000]"));
  EXPECT_GE(photonIntegrator(direct).directMap().size(), 2000u);

  // No indirect photons: no indirect map and nothing to gather from.
  auto none = test::buildSceneText(test::causticRoom(
      4, 1, "\"photonmap\" \"integer indirectphotons\" [0] \"integer causticphotons\" [0]"));
  EXPECT_TRUE(photonIntegrator(none).indirectMap().empty());
  EXPECT_TRUE(photonIntegrator(none).radianceMap().empty());
  EXPECT_TRUE(photonIntegrator(none).buildCounts().empty());
  EXPECT_TRUE(photonIntegrator(none).statsReport().empty());
}

TEST(PhotonMapBuild, AMapThatCannotFillGivesUpWithAWarning) {
  // A mirror sphere outside a narrow spotlight's cone: light reaches it only after a diffuse
  // bounce, so no path is ever a caustic one. pbrt-v2 gives up past 500,000 paths.
  std::string scene =
      "LookAt 0 0 -0.95  0 -0.2 1  0 1 0\nCamera \"perspective\"\n"
      "Film \"image\" \"integer xresolution\" [4] \"integer yresolution\" [4]\n"
      "SurfaceIntegrator \"photonmap\" \"integer causticphotons\" [100] "
      "\"integer indirectphotons\" [1000]\nWorldBegin\n"
      "LightSource \"spot\" \"point from\" [0 0.9 0] \"point to\" [0 -1 0] "
      "\"float coneangle\" [10] \"rgb I\" [5 5 5]\n"
      "Material \"matte\"\nShape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3]\n"
      "  \"point P\" [-1 -1 -1  1 -1 -1  1 -1 1  -1 -1 1]\n"
      "AttributeBegin\nMaterial \"mirror\"\nTranslate 0.7 -0.7 0.5\n"
      "Shape \"sphere\" \"float radius\" [0.2]\nAttributeEnd\nWorldEnd\n";
  std::vector<std::string> warnings;
  BuildOptions o;
  o.warn = [&](const FileLoc& loc, const std::string& message) {
    warnings.push_back(loc.str() + ": " + message);
  };
  auto r = test::buildSceneText(scene, o);
  const PhotonMapIntegrator& pm = photonIntegrator(r);
  EXPECT_TRUE(pm.causticMap().empty());
  EXPECT_GE(pm.indirectMap().size(), 1000u);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("test.pbrt:4"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("caustic photon map stored only 0 photons"), std::string::npos)
      << warnings[0];
}

TEST(PhotonMapBuild, FewerIndirectPhotonsThanTheGatherWantsStillRenders) {
  // The final gather looks for 50 photon directions; pbrt-v2's radius doubling would never end
  // on a map with fewer.
  auto r = render(test::causticRoom(4, 1,
                                    "\"photonmap\" \"integer indirectphotons\" [10] "
                                    "\"integer causticphotons\" [0]"),
                  2, 16);
  EXPECT_LT(photonIntegrator(r).indirectMap().size(), 50u);
  for (float v : r.film().image().data) ASSERT_TRUE(std::isfinite(v));
}

TEST(PhotonMapBuild, PhotonsSpanTheShutterAsCameraRaysDo) {
  // A floor rising from y = -1 to y = -0.5 over the shutter, under a point light: the direct
  // photons lie at the heights the floor passes through, uniformly in time.
  auto scene = [](const std::string& shutter) {
    return "LookAt 0 0 -3  0 0 0  0 1 0\nCamera \"perspective\" " + shutter +
           "\nFilm \"image\" \"integer xresolution\" [4] \"integer yresolution\" [4]\n"
           "SurfaceIntegrator \"photonmap\" \"bool directwithphotons\" \"true\" "
           "\"integer directphotons\" [4000] \"integer indirectphotons\" [0] "
           "\"integer causticphotons\" [0] \"bool finalgather\" \"false\"\nWorldBegin\n"
           "LightSource \"point\" \"point from\" [0 1 0]\nMaterial \"matte\"\n"
           "ActiveTransform StartTime\nTranslate 0 -1 0\nActiveTransform EndTime\n"
           "Translate 0 -0.5 0\nActiveTransform All\n"
           "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3]\n"
           "  \"point P\" [-50 0 -50  50 0 -50  50 0 50  -50 0 50]\nWorldEnd\n";
  };
  auto moving = test::buildSceneText(scene(""));
  const PhotonMap& m = photonIntegrator(moving).directMap();
  ASSERT_GE(m.size(), 4000u);
  double lo = 0, hi = -2, sum = 0;
  for (const Photon& p : m.photons()) {
    lo = std::min(lo, double(p.p.y));
    hi = std::max(hi, double(p.p.y));
    sum += p.p.y;
  }
  EXPECT_NEAR(lo, -1, 0.01);
  EXPECT_NEAR(hi, -0.5, 0.01);
  // Low-discrepancy times: the mean height is that of mid-shutter, to well within 1%.
  EXPECT_NEAR(sum / double(m.size()), -0.75, 0.005);
  auto still = test::buildSceneText(scene("\"float shutteropen\" [0] \"float shutterclose\" [0]"));
  for (const Photon& p : photonIntegrator(still).directMap().photons())
    ASSERT_NEAR(p.p.y, -1, 1e-4);
}

TEST(PhotonMapBuild, QuickShootsATenthOfThePhotons) {
  std::string scene = test::causticRoom(4, 1, kSmallPhotonMap);
  BuildOptions quick;
  quick.quick = true;
  auto r = test::buildSceneText(scene, quick);
  const PhotonMapIntegrator& pm = photonIntegrator(r);
  EXPECT_GE(pm.causticMap().size(), 100u);
  EXPECT_LT(pm.causticMap().size(), 110u);
  EXPECT_GE(pm.indirectMap().size(), 400u);
  EXPECT_LT(pm.indirectMap().size(), 410u);
  EXPECT_EQ(pm.settings().nUsed, 5);
  EXPECT_EQ(pm.settings().finalGatherSamples, 2);
}

}  // namespace
}  // namespace candela
