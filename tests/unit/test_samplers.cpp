// Samplers: every value a pure function of (pixel, sample index, dimension, seed); the stratified
// sampler puts one sample in each stratum of every dimension; the factory's names and counts.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <vector>

#include "filters/box_filter.h"
#include "filters/gaussian_filter.h"
#include "integrators/integrator.h"
#include "samplers/halton_sampler.h"
#include "samplers/random_sampler.h"
#include "samplers/sampler.h"
#include "samplers/stratified_sampler.h"
#include "support/param_items.h"
#include "support/render_scene.h"

namespace candela {
namespace {

// The values of one pixel sample: pixel 2D, then 1D, 2D, 1D, 2D, ... for `dims` dimensions.
std::vector<Float> sampleValues(Sampler& s, Point2i pixel, int index, int dims) {
  s.startPixelSample(pixel, index);
  std::vector<Float> v;
  Point2f p = s.getPixel2D();
  v.push_back(p.x);
  v.push_back(p.y);
  for (int d = 0; d < dims; ++d) {
    if (d % 2 == 0) {
      v.push_back(s.get1D());
    } else {
      Point2f q = s.get2D();
      v.push_back(q.x);
      v.push_back(q.y);
    }
  }
  return v;
}

TEST(StratifiedSampler, EachStratumOncePerPixelPerDimension) {
  const int xs = 3, ys = 2, n = xs * ys;
  StratifiedSampler sampler(xs, ys, true, 42);
  EXPECT_EQ(sampler.samplesPerPixel(), n);
  for (Point2i pixel : {Point2i(0, 0), Point2i(17, 3), Point2i(-4, 250)}) {
    std::vector<std::vector<Float>> all;
    for (int i = 0; i < n; ++i) all.push_back(sampleValues(sampler, pixel, i, 6));
    // Layout: [pixel.x, pixel.y] then 1D, (2D x, y), 1D, (2D), 1D, (2D).
    auto strata2D = [&](size_t at) {
      std::set<std::pair<int, int>> hit;
      for (const auto& v : all) hit.insert({int(v[at] * xs), int(v[at + 1] * ys)});
      return hit.size();
    };
    auto strata1D = [&](size_t at) {
      std::set<int> hit;
      for (const auto& v : all) hit.insert(int(v[at] * n));
      return hit.size();
    };
    EXPECT_EQ(strata2D(0), size_t(n)) << "pixel dimension";
    for (size_t at : {2, 5, 8}) EXPECT_EQ(strata1D(at), size_t(n)) << "1D at " << at;
    for (size_t at : {3, 6, 9}) EXPECT_EQ(strata2D(at), size_t(n)) << "2D at " << at;
  }
}

TEST(StratifiedSampler, DimensionsArePairedDifferently) {
  // Latin-hypercube-like decorrelation: the stratum of dimension 0 does not determine that of
  // dimension 1 in the same way in every pixel.
  StratifiedSampler sampler(4, 4, true, 7);
  int identical = 0;
  for (int px = 0; px < 50; ++px) {
    std::vector<int> a, b;
    for (int i = 0; i < 16; ++i) {
      sampler.startPixelSample(Point2i(px, 0), i);
      a.push_back(int(sampler.get1D() * 16));
      b.push_back(int(sampler.get1D() * 16));
    }
    if (a == b) ++identical;
  }
  EXPECT_LT(identical, 2);
}

TEST(StratifiedSampler, WithoutJitterValuesAreStratumCentres) {
  StratifiedSampler sampler(2, 2, false, 1);
  for (int i = 0; i < 4; ++i) {
    sampler.startPixelSample(Point2i(3, 4), i);
    Point2f p = sampler.getPixel2D();
    EXPECT_TRUE(p.x == 0.25f || p.x == 0.75f);
    EXPECT_TRUE(p.y == 0.25f || p.y == 0.75f);
    Float t = sampler.get1D();
    EXPECT_EQ(std::fmod(t * 8, 2.f), 1.f) << t;  // (k + 0.5) / 4
  }
}

TEST(StratifiedSampler, SameValuesRegardlessOfOrderAndClone) {
  StratifiedSampler sampler(3, 3, true, 1234);
  std::map<std::pair<int, int>, std::vector<Float>> forward;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x)
      for (int i = 0; i < 9; ++i) forward[{y * 4 + x, i}] = sampleValues(sampler, {x, y}, i, 8);
  auto copy = sampler.clone();
  for (int y = 3; y >= 0; --y)
    for (int i = 8; i >= 0; --i)
      for (int x = 3; x >= 0; --x)
        ASSERT_EQ(sampleValues(*copy, {x, y}, i, 8), (forward[{y * 4 + x, i}]));
  // getPixel2D gives the same point whenever in the sample it is asked for.
  sampler.startPixelSample(Point2i(2, 1), 5);
  sampler.get1D();
  sampler.get2D();
  Point2f late = sampler.getPixel2D();
  EXPECT_EQ(late.x, (forward[{1 * 4 + 2, 5}][0]));
  EXPECT_EQ(late.y, (forward[{1 * 4 + 2, 5}][1]));
}

TEST(StratifiedSampler, DifferentPixelsAndSeedsDiffer) {
  StratifiedSampler a(2, 2, true, 5), b(2, 2, true, 6);
  EXPECT_NE(sampleValues(a, {0, 0}, 0, 4), sampleValues(a, {1, 0}, 0, 4));
  EXPECT_NE(sampleValues(a, {0, 0}, 0, 4), sampleValues(a, {0, 1}, 0, 4));
  EXPECT_NE(sampleValues(a, {0, 0}, 0, 4), sampleValues(b, {0, 0}, 0, 4));
}

TEST(StratifiedSampler, ValuesInUnitIntervalEvenPastSamplesPerPixel) {
  StratifiedSampler sampler(5, 3, true, 77);
  for (int px = 0; px < 20; ++px)
    for (int i = 0; i < 40; ++i)
      for (Float v : sampleValues(sampler, {px, 2 * px}, i, 12)) {
        ASSERT_GE(v, 0.f);
        ASSERT_LT(v, 1.f);
      }
  // The second block of 15 samples is stratified too.
  std::set<int> hit;
  for (int i = 15; i < 30; ++i) {
    sampler.startPixelSample(Point2i(1, 1), i);
    hit.insert(int(sampler.get1D() * 15));
  }
  EXPECT_EQ(hit.size(), 15u);
}

TEST(RandomSampler, DeterministicUniformAndPixelDependent) {
  RandomSampler sampler(4, 9);
  EXPECT_EQ(sampler.samplesPerPixel(), 4);
  auto clone = sampler.clone();
  std::vector<Float> first = sampleValues(sampler, {10, 20}, 3, 10);
  sampleValues(sampler, {11, 20}, 0, 10);  // unrelated work in between
  EXPECT_EQ(sampleValues(*clone, {10, 20}, 3, 10), first);
  EXPECT_EQ(sampleValues(sampler, {10, 20}, 3, 10), first);
  EXPECT_NE(sampleValues(sampler, {10, 21}, 3, 10), first);
  EXPECT_NE(sampleValues(sampler, {10, 20}, 2, 10), first);
  EXPECT_NE(sampleValues(*RandomSampler(4, 10).clone(), {10, 20}, 3, 10), first);
  // Mean and spread of many values.
  double sum = 0, sumSq = 0;
  int count = 0;
  for (int px = 0; px < 100; ++px)
    for (int i = 0; i < 4; ++i)
      for (Float v : sampleValues(sampler, {px, -px}, i, 20)) {
        ASSERT_GE(v, 0.f);
        ASSERT_LT(v, 1.f);
        sum += v;
        sumSq += double(v) * v;
        ++count;
      }
  double mean = sum / count, var = sumSq / count - mean * mean;
  EXPECT_NEAR(mean, 0.5, 0.01);
  EXPECT_NEAR(var, 1.0 / 12, 0.005);
}

TEST(Sampler, CameraSampleLiesWithinTheFilterSupport) {
  StratifiedSampler sampler(2, 2, true, 3);
  BoxFilter box(Vector2f(0.5f, 0.5f));
  GaussianFilter gauss(Vector2f(2, 1), 2);
  for (int i = 0; i < 4; ++i) {
    Point2i pixel(12, 34);
    sampler.startPixelSample(pixel, i);
    CameraSample cs = getCameraSample(sampler, pixel, box);
    EXPECT_GE(cs.pFilm.x, 12.f);
    EXPECT_LE(cs.pFilm.x, 13.f);
    EXPECT_GE(cs.pFilm.y, 34.f);
    EXPECT_LE(cs.pFilm.y, 35.f);
    EXPECT_FLOAT_EQ(cs.filterWeight, 1.f);
    EXPECT_GE(cs.time, 0.f);
    EXPECT_LT(cs.time, 1.f);
    EXPECT_LT(cs.pLens.x, 1.f);
    sampler.startPixelSample(pixel, i);
    cs = getCameraSample(sampler, pixel, gauss);
    EXPECT_LE(std::abs(cs.pFilm.x - 12.5f), 2.f);
    EXPECT_LE(std::abs(cs.pFilm.y - 34.5f), 1.f);
    EXPECT_GT(cs.filterWeight, 0.f);
  }
}

// Without the lens, a camera sample has the same film position, weight and time, pLens (0, 0),
// and the dimensions after it keep their values (the Halton sampler skips computing the lens
// ones; the others take them and drop them).
TEST(Sampler, CameraSampleWithoutTheLensLeavesTheOtherDimensionsAlone) {
  BoxFilter box(Vector2f(0.5f, 0.5f));
  FileLoc loc{"s.pbrt", 1, 1};
  for (const char* name : {"halton", "random", "stratified", "sobol"}) {
    SCOPED_TRACE(name);
    auto sampler = createSampler(name, ParamSet(), 7, 16, loc);
    auto* halton = dynamic_cast<HaltonSampler*>(sampler.get());
    EXPECT_EQ(halton != nullptr, std::string(name) == "halton");
    for (int i = 0; i < 16; ++i) {
      Point2i pixel(i % 5, 3 + i);
      std::vector<Float> after[2];
      CameraSample cs[2];
      for (int lens = 0; lens < 2; ++lens) {
        sampler->startPixelSample(pixel, i);
        cs[lens] = halton ? getCameraSample(*halton, pixel, box, lens == 1)
                          : getCameraSample(*sampler, pixel, box, lens == 1);
        // Past the camera sample, as a path takes them; far enough for the Halton sampler's
        // coordinates to be keyed past the lens ones.
        for (int d = 0; d < 12; ++d) {
          Point2f u = sampler->get2D();
          after[lens].insert(after[lens].end(), {sampler->get1D(), u.x, u.y});
        }
      }
      EXPECT_EQ(cs[0].pFilm, cs[1].pFilm);
      EXPECT_EQ(cs[0].time, cs[1].time);
      EXPECT_EQ(cs[0].filterWeight, cs[1].filterWeight);
      EXPECT_EQ(cs[0].pLens, Point2f(0, 0));
      EXPECT_NE(cs[1].pLens, Point2f(0, 0));
      EXPECT_EQ(after[0], after[1]);
    }
  }
}

// IntegratorContext::skip1D passes over one value: the values after it are those that follow a
// value taken with get1D (the Halton sampler skips computing it; the others take and drop it).
TEST(Sampler, IntegratorContextSkip1DLeavesTheLaterValuesAlone) {
  FileLoc loc{"s.pbrt", 1, 1};
  MemoryArena arena;
  RayStats stats;
  for (const char* name : {"halton", "random", "stratified", "sobol"}) {
    SCOPED_TRACE(name);
    auto sampler = createSampler(name, ParamSet(), 7, 16, loc);
    IntegratorContext ctx{*sampler, arena, stats};
    EXPECT_EQ(ctx.halton != nullptr, std::string(name) == "halton");
    for (int i = 0; i < 16; ++i) {
      Point2i pixel(i % 5, 3 + i);
      std::vector<Float> after[2];
      for (int passedOver = 0; passedOver < 2; ++passedOver) {
        sampler->startPixelSample(pixel, i);
        // Values passed over at several depths of a path: each vertex draws (1D, 2D) and then
        // the 1D value is taken or passed over.
        for (int d = 0; d < 10; ++d) {
          Point2f u = ctx.get2D();
          after[passedOver].insert(after[passedOver].end(), {u.x, u.y});
          if (passedOver)
            ctx.skip1D();
          else
            ctx.get1D();
          after[passedOver].push_back(ctx.get1D());
        }
      }
      EXPECT_EQ(after[0], after[1]);
    }
  }
}

// A pixel's camera samples taken first, a group at a time, and each sample then started again
// past them (skipCameraSample), as the renderer does when it traces camera rays together: every
// sampler gives the same camera samples and the same values after them as taking one sample at a
// time.
TEST(Sampler, SamplesStartedAgainPastTheirCameraSampleKeepTheirValues) {
  BoxFilter box(Vector2f(0.5f, 0.5f));
  FileLoc loc{"s.pbrt", 1, 1};
  for (const char* name : {"random", "stratified", "lowdiscrepancy", "halton", "bestcandidate",
                           "adaptive", "02sequence", "maxmindist", "sobol"}) {
    SCOPED_TRACE(name);
    auto sampler = createSampler(name, ParamSet(), 7, 16, loc);
    const int spp = sampler->samplesPerPixel();
    for (int p = 0; p < 6; ++p) {
      Point2i pixel(p % 4, 2 + 3 * p);
      std::vector<CameraSample> oneByOne, grouped;
      std::vector<std::vector<Float>> afterOne, afterGrouped;
      auto valuesAfter = [&] {
        std::vector<Float> v;
        for (int d = 0; d < 12; ++d) {
          Point2f u = sampler->get2D();
          v.insert(v.end(), {sampler->get1D(), u.x, u.y});
        }
        return v;
      };
      for (int i = 0; i < spp; ++i) {
        sampler->startPixelSample(pixel, i);
        oneByOne.push_back(getCameraSample(*sampler, pixel, box));
        afterOne.push_back(valuesAfter());
      }
      for (int g = 0; g < spp; g += 8) {
        const int e = std::min(spp, g + 8);
        for (int i = g; i < e; ++i) {
          sampler->startPixelSample(pixel, i);
          grouped.push_back(getCameraSample(*sampler, pixel, box));
        }
        for (int i = g; i < e; ++i) {
          sampler->startPixelSample(pixel, i);
          skipCameraSample(*sampler);
          afterGrouped.push_back(valuesAfter());
        }
      }
      ASSERT_EQ(grouped.size(), oneByOne.size());
      for (size_t i = 0; i < grouped.size(); ++i) {
        EXPECT_EQ(grouped[i].pFilm, oneByOne[i].pFilm) << i;
        EXPECT_EQ(grouped[i].pLens, oneByOne[i].pLens) << i;
        EXPECT_EQ(grouped[i].time, oneByOne[i].time) << i;
        EXPECT_EQ(afterGrouped[i], afterOne[i]) << i;
      }
    }
  }
}

TEST(SamplerFactory, DefaultsAndParameters) {
  FileLoc loc{"s.pbrt", 1, 1};
  auto random = createSampler("random", ParamSet(), 1, 0, loc);
  EXPECT_EQ(random->samplesPerPixel(), 4);
  auto strat = createSampler("stratified", ParamSet(), 1, 0, loc);
  auto* s = dynamic_cast<StratifiedSampler*>(strat.get());
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->xSamples(), 2);
  EXPECT_EQ(s->ySamples(), 2);
  EXPECT_TRUE(s->jitter());

  ParamSet ps;
  ps.add(test::ints("xsamples", {3}));
  ps.add(test::ints("ysamples", {5}));
  ps.add(test::bools("jitter", {false}));
  strat = createSampler("stratified", ps, 1, 0, loc);
  EXPECT_EQ(strat->samplesPerPixel(), 15);
  EXPECT_FALSE(dynamic_cast<StratifiedSampler&>(*strat).jitter());

  // lrt's "integer jitter" 0.
  ParamSet lrt;
  lrt.add(test::ints("jitter", {0}));
  EXPECT_FALSE(
      dynamic_cast<StratifiedSampler&>(*createSampler("stratified", lrt, 1, 0, loc)).jitter());

  ParamSet rp;
  rp.add(test::ints("pixelsamples", {9}));
  EXPECT_EQ(createSampler("random", rp, 1, 0, loc)->samplesPerPixel(), 9);
  // The stratified sampler takes a pixelsamples count as strata when xsamples/ysamples are absent.
  auto fromCount = createSampler("stratified", rp, 1, 0, loc);
  EXPECT_EQ(dynamic_cast<StratifiedSampler&>(*fromCount).xSamples(), 3);
  EXPECT_EQ(fromCount->samplesPerPixel(), 9);
}

TEST(SamplerFactory, SppOverride) {
  FileLoc loc;
  EXPECT_EQ(createSampler("random", ParamSet(), 1, 7, loc)->samplesPerPixel(), 7);
  for (int spp : {1, 2, 7, 12, 16, 64, 100}) {
    auto s = createSampler("stratified", ParamSet(), 1, spp, loc);
    EXPECT_EQ(s->samplesPerPixel(), spp);
    auto& st = dynamic_cast<StratifiedSampler&>(*s);
    EXPECT_GE(st.xSamples(), st.ySamples());
  }
  auto square = createSampler("stratified", ParamSet(), 1, 16, loc);
  EXPECT_EQ(dynamic_cast<StratifiedSampler&>(*square).xSamples(), 4);
}

TEST(SamplerFactory, ErrorsNameTheProblem) {
  try {
    createSampler("pmj02bn", ParamSet(), 1, 0, FileLoc{"x.pbrt", 9, 1});
    FAIL();
  } catch (const SceneError& e) {
    std::string what = e.what();
    EXPECT_NE(what.find("x.pbrt:9:1"), std::string::npos);
    EXPECT_NE(what.find("pmj02bn"), std::string::npos);
    for (const char* known : {"random", "stratified", "lowdiscrepancy", "halton", "bestcandidate",
                              "adaptive", "02sequence", "maxmindist", "sobol"})
      EXPECT_NE(what.find(known), std::string::npos) << what;
  }
  ParamSet ps;
  ps.add(test::ints("xsamples", {0}, FileLoc{"samplers.pbrt", 5, 3}));
  try {
    createSampler("stratified", ps, 1, 0, FileLoc{"x.pbrt", 1, 1});
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(e.location().line, 5);
  }
}

}  // namespace
}  // namespace candela

namespace candela {
namespace {

// Counts a scene leaves out follow its dialect: pbrt-v2 halton 4, stratified 2 x 2; pbrt-v3
// halton 16, stratified 4 x 4; a given count is the same in both.
TEST(SamplerFactory, DefaultCountsFollowTheDialect) {
  FileLoc loc{"test.pbrt", 1, 1};
  const SamplerDefaults v2 = SamplerDefaults::PbrtV2, v3 = SamplerDefaults::PbrtV3;
  EXPECT_EQ(createSampler("halton", ParamSet(), 1, 0, loc, {}, v2)->samplesPerPixel(), 4);
  EXPECT_EQ(createSampler("halton", ParamSet(), 1, 0, loc, {}, v3)->samplesPerPixel(), 16);
  EXPECT_EQ(createSampler("stratified", ParamSet(), 1, 0, loc, {}, v2)->samplesPerPixel(), 4);
  EXPECT_EQ(createSampler("stratified", ParamSet(), 1, 0, loc, {}, v3)->samplesPerPixel(), 16);
  ParamSet given;
  given.add(test::ints("pixelsamples", {8}));
  EXPECT_EQ(createSampler("halton", given, 1, 0, loc, {}, v3)->samplesPerPixel(), 8);
}

// A pbrt-v3 scene without a Sampler statement gets pbrt-v3's default, halton with 16 samples; a
// pbrt-v2 scene the stratified 2 x 2.
TEST(SamplerFactory, SceneWithoutSamplerGetsItsDialectsDefault) {
  auto spp = [](const std::string& integrator) {
    return test::buildSceneText(
               "Film \"image\" \"integer xresolution\" [4] "
               "\"integer yresolution\" [4]\n" +
               integrator + "\nWorldBegin\nWorldEnd\n")
        .job()
        .sampler->samplesPerPixel();
  };
  EXPECT_EQ(spp("Integrator \"path\""), 16);
  EXPECT_EQ(spp("SurfaceIntegrator \"path\""), 4);
}

}  // namespace
}  // namespace candela
