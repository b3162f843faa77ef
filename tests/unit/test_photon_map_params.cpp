// SurfaceIntegrator "photonmap" / "exphotonmap": pbrt-v2's defaults, the lrt draft's names, and a
// located SceneError for every bad value.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "assembly/plugin_factories.h"
#include "integrators/photon_map_params.h"
#include "support/param_items.h"

namespace candela {
namespace {

const FileLoc kStatement{"s.pbrt", 3, 1};
const FileLoc kParam{"s.pbrt", 7, 5};

PluginDesc desc(std::vector<ParamItem> items, const std::string& name = "photonmap") {
  PluginDesc d{name, {}, kStatement};
  for (ParamItem& item : items) d.params.add(std::move(item));
  return d;
}

PhotonMapSettings settingsOf(const PluginDesc& d) { return photonMapSettings(d.params, d.loc); }

TEST(PhotonMapParams, DefaultsArePbrtV2s) {
  PhotonMapSettings s = settingsOf(desc({}));
  EXPECT_EQ(s.causticPhotons, 20000);
  EXPECT_EQ(s.indirectPhotons, 100000);
  EXPECT_EQ(s.nUsed, 50);
  EXPECT_EQ(s.maxSpecularDepth, 5);
  EXPECT_EQ(s.maxPhotonDepth, 5);
  EXPECT_TRUE(s.finalGather);
  EXPECT_EQ(s.finalGatherSamples, 32);
  EXPECT_FLOAT_EQ(s.maxDist, 0.1f);
  EXPECT_FLOAT_EQ(s.gatherAngle, 10);
  EXPECT_FALSE(s.directWithPhotons);
  EXPECT_EQ(s.nFilter, 0);
}

TEST(PhotonMapParams, LrtDraftNamesAndIntegerFlags) {
  PhotonMapSettings s =
      settingsOf(desc({test::ints("maxdepth", {7}), test::ints("finalgather", {0}),
                       test::ints("directwithphotons", {1}), test::ints("directphotons", {1234}),
                       test::ints("nfilter", {4})}));
  EXPECT_EQ(s.maxSpecularDepth, 7);
  EXPECT_FALSE(s.finalGather);
  EXPECT_TRUE(s.directWithPhotons);
  EXPECT_EQ(s.directPhotons, 1234);
  EXPECT_EQ(s.nFilter, 4);
  EXPECT_FALSE(settingsOf(desc({test::bools("finalgather", {false})})).finalGather);
}

TEST(PhotonMapParams, BothNamesMakeTheSameIntegrator) {
  for (const char* name : {"photonmap", "exphotonmap"}) {
    auto integrator = createSurfaceIntegrator(desc({test::ints("nused", {20})}, name));
    ASSERT_NE(dynamic_cast<PhotonMapIntegrator*>(integrator.get()), nullptr) << name;
    EXPECT_EQ(dynamic_cast<PhotonMapIntegrator&>(*integrator).settings().nUsed, 20);
  }
}

// The error must name the parameter's own location, not the statement's.
void expectLocatedError(std::vector<ParamItem> items, const std::string& mentions) {
  try {
    settingsOf(desc(std::move(items)));
    ADD_FAILURE() << "no error for " << mentions;
  } catch (const SceneError& e) {
    EXPECT_EQ(e.location().line, kParam.line) << e.what();
    EXPECT_EQ(e.location().file, kParam.file) << e.what();
    EXPECT_NE(std::string(e.what()).find(mentions), std::string::npos) << e.what();
  }
}

TEST(PhotonMapParams, EveryBadValueIsALocatedSceneError) {
  for (const char* count : {"causticphotons", "indirectphotons", "directphotons", "nfilter"})
    expectLocatedError({test::ints(count, {-1}, kParam)}, count);
  for (const char* positive : {"nused", "maxphotondepth", "finalgathersamples"})
    expectLocatedError({test::ints(positive, {0}, kParam)}, positive);
  expectLocatedError({test::ints("maxspeculardepth", {-1}, kParam)}, "maxspeculardepth");
  expectLocatedError({test::ints("maxdepth", {-2}, kParam)}, "maxdepth");
  expectLocatedError({test::ints("maxspeculardepth", {100000}, kParam)}, "maxspeculardepth");
  expectLocatedError({test::ints("maxspeculardepth", {3}), test::ints("maxdepth", {3}, kParam)},
                     "not both");
  for (Float bad : {0.f, -0.5f, std::numeric_limits<Float>::infinity(), std::nanf("")})
    expectLocatedError({test::floats("maxdist", {bad}, kParam)}, "maxdist");
  for (Float bad : {0.f, -10.f, 180.f, 270.f})
    expectLocatedError({test::floats("gatherangle", {bad}, kParam)}, "gatherangle");
  expectLocatedError({test::strings("finalgather", {"yes"}, kParam)}, "finalgather");
  expectLocatedError({test::ints("directwithphotons", {1, 0}, kParam)}, "directwithphotons");
  // A wrongly typed count is the ParamSet's own located error.
  expectLocatedError({test::floats("nused", {5}, kParam)}, "nused");
}

}  // namespace
}  // namespace candela
