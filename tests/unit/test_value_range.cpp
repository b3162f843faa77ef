// ParamSet's range-checked getters: each rule has one wording, reported at the value's
// file:line:col (the statement's when the parameter is absent), and the boundaries are where the
// rule says.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/paramset.h"
#include "core/value_range.h"
#include "support/param_items.h"
#include "support/render_scene.h"
#include "support/scene_error_of.h"

using namespace candela;

namespace {

using test::sceneErrorOf;

constexpr double kInf = std::numeric_limits<double>::infinity();
const double kNaN = std::nan("");

TEST(ValueRange, BoundariesAreWhereTheRuleSays) {
  EXPECT_TRUE(ValueRange::atLeast(1).contains(1));
  EXPECT_FALSE(ValueRange::atLeast(1).contains(0.999));
  EXPECT_TRUE(ValueRange::atLeast(0).contains(kInf));  // "at least" bounds one side only
  EXPECT_FALSE(ValueRange::greaterThan(0).contains(0));
  EXPECT_TRUE(ValueRange::greaterThan(0).contains(kInf));
  EXPECT_FALSE(ValueRange::positive().contains(0));
  EXPECT_FALSE(ValueRange::positive().contains(kInf));
  EXPECT_TRUE(ValueRange::nonNegative().contains(0));
  EXPECT_FALSE(ValueRange::nonNegative().contains(-1e-30));
  EXPECT_FALSE(ValueRange::nonNegative().contains(kInf));
  EXPECT_TRUE(ValueRange::within(0, 1).contains(0));
  EXPECT_TRUE(ValueRange::within(0, 1).contains(1));
  EXPECT_FALSE(ValueRange::between(-1, 1).contains(-1));
  EXPECT_FALSE(ValueRange::between(-1, 1).contains(1));
  EXPECT_TRUE(ValueRange::between(-1, 1).contains(0.999));
  EXPECT_FALSE(ValueRange::aboveUpTo(0, 90).contains(0));
  EXPECT_TRUE(ValueRange::aboveUpTo(0, 90).contains(90));
  EXPECT_FALSE(ValueRange::finite().contains(-kInf));
  // NaN lies in no range, not even "any number".
  for (const ValueRange& r :
       {ValueRange::any(), ValueRange::finite(), ValueRange::positive(), ValueRange::nonNegative(),
        ValueRange::atLeast(0), ValueRange::greaterThan(0), ValueRange::within(0, 1),
        ValueRange::between(0, 1), ValueRange::aboveUpTo(0, 1)})
    EXPECT_FALSE(r.contains(kNaN)) << r.describe();
}

TEST(ValueRange, OneWordingPerRule) {
  EXPECT_EQ(ValueRange::atLeast(1).describe(), "at least 1");
  EXPECT_EQ(ValueRange::greaterThan(0).describe(), "greater than 0");
  EXPECT_EQ(ValueRange::positive().describe(), "positive and finite");
  EXPECT_EQ(ValueRange::nonNegative().describe(), "non-negative and finite");
  EXPECT_EQ(ValueRange::within(0, 1).describe(), "within [0, 1]");
  EXPECT_EQ(ValueRange::between(-1, 1).describe(), "within (-1, 1)");
  EXPECT_EQ(ValueRange::aboveUpTo(0, 90).describe(), "within (0, 90]");
  EXPECT_EQ(formatNumber(0.25), "0.25");
  EXPECT_EQ(formatNumber(-3), "-3");
  EXPECT_EQ(formatNumber(kInf), "inf");
}

TEST(ParamSetRanges, OutOfRangeIsLocatedAtTheValue) {
  ParamSet ps;
  ps.add(test::ints("nsamples", {0}, FileLoc{"a.pbrt", 4, 11}));
  ps.add(test::floats("g", {1}, FileLoc{"a.pbrt", 5, 3}));
  const FileLoc statement{"a.pbrt", 3, 1};
  EXPECT_EQ(sceneErrorOf([&] { ps.getOneInt("nsamples", 1, ValueRange::atLeast(1), statement); }),
            "a.pbrt:4:11: error: \"nsamples\" must be at least 1 (got 0)");
  EXPECT_EQ(sceneErrorOf([&] { ps.getOneFloat("g", 0, ValueRange::between(-1, 1), statement); }),
            "a.pbrt:5:3: error: \"g\" must be within (-1, 1) (got 1)");
  // A value inside the range is returned, and counts as used.
  EXPECT_EQ(ps.getOneInt("nsamples", 1, ValueRange::atLeast(0), statement), 0);
  int unused = 0;
  ps.forEachUnused([&](const ParamItem&) { ++unused; });
  EXPECT_EQ(unused, 0);
}

TEST(ParamSetRanges, AbsentNamesGiveTheDefaultOrTheStatementsLocation) {
  ParamSet ps;
  const FileLoc statement{"b.pbrt", 9, 1};
  EXPECT_EQ(ps.getOneFloat("radius", 2, ValueRange::positive(), statement), 2);
  EXPECT_EQ(
      sceneErrorOf([&] { ps.requireInRange("sigma_a", -1, ValueRange::nonNegative(), statement); }),
      "b.pbrt:9:1: error: \"sigma_a\" must be non-negative and finite (got -1)");
}

TEST(ParamSetRanges, OneOfASetNamesTheSet) {
  ParamSet ps;
  ps.add(test::strings("strategy", {"some"}, FileLoc{"c.pbrt", 2, 7}));
  EXPECT_EQ(sceneErrorOf([&] {
              ps.getOneString("strategy", "all", {"all", "one"}, FileLoc{});
            }),
            "c.pbrt:2:7: error: \"strategy\" must be one of all, one (got \"some\")");
  EXPECT_EQ(ps.getOneString("other", "one", {"all", "one"}, FileLoc{}), "one");
}

// The factories word a rule alike wherever it is (once "nsamples must be >= 1", "numiterations
// must be >= 1" and "nused must be >= 1; got 0"): scenes with a count of 0 where at least 1 is
// needed, each an error at the value.
TEST(ParamSetRanges, FactoriesWordTheSameRuleAlike) {
  const std::string world = "WorldBegin\nLightSource \"point\"\nShape \"sphere\"\nWorldEnd\n";
  const struct {
    std::string statement, name;
  } cases[] = {
      {"SurfaceIntegrator \"irradiancecache\" \"integer nsamples\" [0]", "nsamples"},
      {"SurfaceIntegrator \"igi\" \"integer nsets\" [0]", "nsets"},
      {"SurfaceIntegrator \"photonmap\" \"integer nused\" [0]", "nused"},
      {"Integrator \"sppm\" \"integer numiterations\" [0]", "numiterations"},
      {"Integrator \"mlt\" \"integer chains\" [0]", "chains"},
  };
  for (const auto& c : cases) {
    std::string text = "Camera \"perspective\"\n" + c.statement + "\n" + world;
    std::string message = sceneErrorOf([&] { test::buildSceneText(text); });
    EXPECT_NE(message.find(":2:"), std::string::npos) << message;
    EXPECT_NE(message.find("\"" + c.name + "\" must be at least 1 (got 0)"), std::string::npos)
        << message;
  }
}

}  // namespace

namespace {

// Materials whose parameters may be textures check their constant values the same way.
TEST(ParamSetRanges, MaterialConstantsAreCheckedAlike) {
  const struct {
    std::string material, expected;
  } cases[] = {
      {"Material \"disney\" \"float metallic\" [2]", "\"metallic\" must be within [0, 1] (got 2)"},
      {"Material \"hair\" \"float beta_m\" [0]", "\"beta_m\" must be within (0, 1] (got 0)"},
      {"Material \"subsurface\" \"float scale\" [-1]",
       "\"scale\" must be positive and finite (got -1)"},
      {"Material \"subsurface\" \"rgb sigma_a\" [1 -1 1]",
       "\"sigma_a\" must be non-negative and finite (got -1)"},
  };
  for (const auto& c : cases) {
    std::string text = "Camera \"perspective\"\nWorldBegin\nLightSource \"point\"\n" + c.material +
                       "\nShape \"sphere\"\nWorldEnd\n";
    std::string message = sceneErrorOf([&] { test::buildSceneText(text); });
    EXPECT_NE(message.find(":4:"), std::string::npos) << message;
    EXPECT_NE(message.find(c.expected), std::string::npos) << c.material << ": " << message;
  }
}

}  // namespace
