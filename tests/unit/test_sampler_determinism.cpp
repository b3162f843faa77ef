// Every sampler the factory makes: each value a pure function of (pixel, sample index,
// dimension, seed), whatever order pixels and samples are visited in and whichever clone asks
// (the renderer's bit-identical images rest on it); values in [0, 1) with the uniform mean and
// variance; the (0,2)-samplers' power-of-two rounding with a warning; the adaptive sampler's
// decision rules and factory.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "core/rng.h"
#include "samplers/adaptive_sampler.h"
#include "samplers/maxmindist_sampler.h"
#include "samplers/sampler.h"
#include "samplers/sobol_sampler.h"
#include "samplers/zero_two_sequence_sampler.h"
#include "support/param_items.h"

namespace candela {
namespace {

const char* const kSamplers[] = {"random",     "stratified",    "lowdiscrepancy",
                                 "halton",     "bestcandidate", "adaptive",
                                 "02sequence", "maxmindist",    "sobol"};

// The values of one pixel sample: the image plane, then 2D, 1D, 2D, 1D, ...
std::vector<Float> sampleValues(Sampler& s, Point2i pixel, int index, int dims = 8) {
  s.startPixelSample(pixel, index);
  std::vector<Float> v;
  for (int d = 0; d < dims; ++d) {
    if (d % 2 == 0) {
      Point2f p = d == 0 ? s.getPixel2D() : s.get2D();
      v.push_back(p.x);
      v.push_back(p.y);
    } else {
      v.push_back(s.get1D());
    }
  }
  return v;
}

TEST(SamplerDeterminism, SameValuesRegardlessOfVisitingOrderAndClone) {
  for (const char* name : kSamplers) {
    auto sampler = createSampler(name, ParamSet(), 31, 8, FileLoc{});
    const int spp = sampler->samplesPerPixel();
    // In order: pixels row by row, samples in order, with the original sampler.
    std::map<std::pair<int, int>, std::vector<Float>> reference;
    for (int y = 0; y < 6; ++y)
      for (int x = 0; x < 7; ++x)
        for (int s = 0; s < spp; ++s) reference[{y * 7 + x, s}] = sampleValues(*sampler, {x, y}, s);
    // Shuffled (pixel, sample) pairs, spread over two clones, each re-asked after other pixels.
    std::vector<std::pair<int, int>> order;
    for (const auto& [key, values] : reference) order.push_back(key);
    RNG rng(77);
    for (size_t i = order.size() - 1; i > 0; --i)
      std::swap(order[i], order[rng.uniformUInt32(uint32_t(i + 1))]);
    auto a = sampler->clone(), b = sampler->clone();
    for (size_t i = 0; i < order.size(); ++i) {
      auto [pixelIndex, s] = order[i];
      Point2i pixel(pixelIndex % 7, pixelIndex / 7);
      Sampler& which = (i % 2) ? *a : *b;
      ASSERT_EQ(sampleValues(which, pixel, s), reference[order[i]])
          << name << " pixel " << pixel.x << "," << pixel.y << " sample " << s;
    }
    // A fresh sampler with the same parameters and seed agrees; another seed does not.
    const std::vector<Float>& pixel34 = reference[std::make_pair(4 * 7 + 3, 5)];
    auto again = createSampler(name, ParamSet(), 31, 8, FileLoc{});
    EXPECT_EQ(sampleValues(*again, Point2i(3, 4), 5), pixel34) << name;
    auto other = createSampler(name, ParamSet(), 32, 8, FileLoc{});
    EXPECT_NE(sampleValues(*other, Point2i(3, 4), 5), pixel34) << name;
    // Neighbouring pixels differ.
    EXPECT_NE(reference[std::make_pair(0, 0)], reference[std::make_pair(1, 0)]) << name;
  }
}

TEST(SamplerDeterminism, ValuesInUnitIntervalWithUniformMoments) {
  // 200 pixels x 16 samples x 14 values: mean within 0.01 of 1/2 and variance within 0.005 of
  // 1/12 (the standard errors are about 0.0013 and 0.0012 for independent values; stratified
  // ones do better).
  for (const char* name : kSamplers) {
    auto sampler = createSampler(name, ParamSet(), 9, 16, FileLoc{});
    double sum = 0, sumSq = 0;
    int n = 0;
    for (int px = 0; px < 200; ++px)
      for (int s = 0; s < 16; ++s)
        for (Float v : sampleValues(*sampler, {px, 3 * px}, s, 9)) {
          ASSERT_GE(v, 0.f) << name;
          ASSERT_LT(v, 1.f) << name;
          sum += v;
          sumSq += double(v) * v;
          ++n;
        }
    double mean = sum / n, var = sumSq / n - mean * mean;
    EXPECT_NEAR(mean, 0.5, 0.01) << name;
    EXPECT_NEAR(var, 1.0 / 12, 0.005) << name;
  }
}

TEST(SamplerFactory, NewSamplersDefaultsAndPowerOfTwoRounding) {
  FileLoc loc{"s.pbrt", 2, 1};
  std::vector<std::string> warnings;
  SamplerWarning warn = [&](const FileLoc& at, const std::string& m) {
    warnings.push_back(at.str() + " " + m);
  };
  for (const char* name : {"lowdiscrepancy", "halton", "bestcandidate"})
    EXPECT_EQ(createSampler(name, ParamSet(), 1, 0, loc, warn)->samplesPerPixel(), 4) << name;
  EXPECT_TRUE(warnings.empty());
  ParamSet five;
  five.add(test::ints("pixelsamples", {5}, FileLoc{"s.pbrt", 6, 4}));
  EXPECT_EQ(createSampler("lowdiscrepancy", five, 1, 0, loc, warn)->samplesPerPixel(), 8);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("s.pbrt:6:4"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("8"), std::string::npos) << warnings[0];
  // Halton and best-candidate take any count; --spp overrides.
  EXPECT_EQ(createSampler("halton", five, 1, 0, loc, warn)->samplesPerPixel(), 5);
  EXPECT_EQ(createSampler("bestcandidate", five, 1, 0, loc, warn)->samplesPerPixel(), 5);
  EXPECT_EQ(createSampler("halton", five, 1, 3, loc, warn)->samplesPerPixel(), 3);
  EXPECT_EQ(createSampler("lowdiscrepancy", five, 1, 16, loc, warn)->samplesPerPixel(), 16);
  EXPECT_EQ(warnings.size(), 1u);
  EXPECT_THROW(createSampler("bestcandidate", five, 1, 1 << 17, loc, warn), SceneError);
}

TEST(SamplerFactory, PbrtV3SamplersParametersAndPowerOfTwoRounding) {
  FileLoc loc{"v3.pbrt", 4, 1};
  std::vector<std::string> warnings;
  SamplerWarning warn = [&](const FileLoc& at, const std::string& m) {
    warnings.push_back(at.str() + " " + m);
  };
  // pbrt-v3's defaults: 16 samples per pixel, 4 dimensions.
  for (const char* name : {"02sequence", "maxmindist", "sobol"}) {
    auto s = createSampler(name, ParamSet(), 1, 0, loc, warn);
    EXPECT_EQ(s->samplesPerPixel(), 16) << name;
    if (auto* z = dynamic_cast<ZeroTwoSequenceSampler*>(s.get())) {
      EXPECT_EQ(z->dimensions(), 4);
    }
  }
  EXPECT_NE(dynamic_cast<MaxMinDistSampler*>(
                createSampler("maxmindist", ParamSet(), 1, 0, loc, warn).get()),
            nullptr);
  EXPECT_NE(dynamic_cast<SobolSampler*>(createSampler("sobol", ParamSet(), 1, 0, loc, warn).get()),
            nullptr);
  EXPECT_TRUE(warnings.empty());

  ParamSet ps;
  ps.add(test::ints("pixelsamples", {12}, FileLoc{"v3.pbrt", 5, 9}));
  ps.add(test::ints("dimensions", {7}));
  for (const char* name : {"02sequence", "maxmindist", "sobol"}) {
    warnings.clear();
    auto s = createSampler(name, ps, 1, 0, loc, warn);
    EXPECT_EQ(s->samplesPerPixel(), 16) << name;
    if (auto* z = dynamic_cast<ZeroTwoSequenceSampler*>(s.get())) {
      EXPECT_EQ(z->dimensions(), 7);
    }
    ASSERT_EQ(warnings.size(), 1u) << name;
    EXPECT_NE(warnings[0].find("v3.pbrt:5:9"), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find(name), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find("16"), std::string::npos) << warnings[0];
    // --spp overrides, and is rounded with a warning naming it.
    warnings.clear();
    EXPECT_EQ(createSampler(name, ps, 1, 33, loc, warn)->samplesPerPixel(), 64) << name;
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("--spp"), std::string::npos) << warnings[0];
    warnings.clear();
    EXPECT_EQ(createSampler(name, ps, 1, 32, loc, warn)->samplesPerPixel(), 32) << name;
    EXPECT_TRUE(warnings.empty());
  }
  // The max-min-distance matrices stop at 2^16 samples; pbrt-v3 lowers larger counts too.
  warnings.clear();
  EXPECT_EQ(createSampler("maxmindist", ParamSet(), 1, 1 << 17, loc, warn)->samplesPerPixel(),
            1 << 16);
  EXPECT_EQ(warnings.size(), 1u);

  ParamSet bad;
  bad.add(test::ints("dimensions", {0}, FileLoc{"v3.pbrt", 8, 30}));
  for (const char* name : {"02sequence", "maxmindist"}) {
    try {
      createSampler(name, bad, 1, 0, loc, warn);
      FAIL() << name;
    } catch (const SceneError& e) {
      std::string what = e.what();
      EXPECT_NE(what.find("v3.pbrt:8:30"), std::string::npos) << what;
      EXPECT_NE(what.find("dimensions"), std::string::npos) << what;
    }
  }
  ParamSet zero;
  zero.add(test::ints("pixelsamples", {0}, FileLoc{"v3.pbrt", 9, 2}));
  EXPECT_THROW(createSampler("sobol", zero, 1, 0, loc, warn), SceneError);
}

TEST(AdaptiveSampler, FactoryDefaultsAndErrors) {
  FileLoc loc{"a.pbrt", 1, 1};
  auto s = createSampler("adaptive", ParamSet(), 1, 0, loc);
  auto& adaptive = dynamic_cast<AdaptiveSampler&>(*s);
  EXPECT_EQ(adaptive.initialSamplesPerPixel(), 4);
  EXPECT_EQ(adaptive.samplesPerPixel(), 32);
  EXPECT_EQ(adaptive.method(), AdaptiveMethod::Contrast);

  std::vector<std::string> warnings;
  SamplerWarning warn = [&](const FileLoc&, const std::string& m) { warnings.push_back(m); };
  ParamSet ps;
  ps.add(test::ints("minsamples", {3}));
  ps.add(test::ints("maxsamples", {20}));
  ps.add(test::strings("method", {"shapeid"}));
  s = createSampler("adaptive", ps, 1, 0, loc, warn);
  EXPECT_EQ(s->initialSamplesPerPixel(), 4);
  EXPECT_EQ(s->samplesPerPixel(), 32);
  EXPECT_EQ(dynamic_cast<AdaptiveSampler&>(*s).method(), AdaptiveMethod::ShapeId);
  EXPECT_EQ(warnings.size(), 2u);
  // --spp sets maxsamples; minsamples follows it down.
  s = createSampler("adaptive", ParamSet(), 1, 2, loc);
  EXPECT_EQ(s->samplesPerPixel(), 2);
  EXPECT_EQ(s->initialSamplesPerPixel(), 2);

  ParamSet bad;
  bad.add(test::ints("minsamples", {64}));
  EXPECT_THROW(createSampler("adaptive", bad, 1, 0, loc), SceneError);
  ParamSet method;
  method.add(test::strings("method", {"variance"}, FileLoc{"s.pbrt", 7, 4}));
  try {
    createSampler("adaptive", method, 1, 0, loc);
    FAIL();
  } catch (const SceneError& e) {
    std::string what = e.what();
    EXPECT_NE(what.find("s.pbrt:7:4"), std::string::npos) << what;
    EXPECT_NE(what.find("contrast"), std::string::npos) << what;
    EXPECT_NE(what.find("shapeid"), std::string::npos) << what;
  }
}

TEST(AdaptiveSampler, DecisionRules) {
  AdaptiveSampler contrast(4, 32, AdaptiveMethod::Contrast, 1);
  auto results = [](std::vector<Float> ys, std::vector<uint64_t> ids) {
    std::vector<PixelSampleResult> r;
    for (size_t i = 0; i < ys.size(); ++i) r.push_back({Spectrum(ys[i]), ids[i]});
    return r;
  };
  // Luminance of a grey Spectrum(v) is v. Mean 1: within +-0.5 is uniform enough.
  EXPECT_FALSE(contrast.needsMoreSamples(results({1, 1.4f, 0.6f, 1}, {1, 2, 3, 4})));
  EXPECT_TRUE(contrast.needsMoreSamples(results({1, 1.6f, 0.4f, 1}, {1, 1, 1, 1})));
  EXPECT_TRUE(contrast.needsMoreSamples(results({0, 0, 0, 4}, {0, 0, 0, 0})));
  EXPECT_FALSE(contrast.needsMoreSamples(results({0, 0, 0, 0}, {1, 2, 0, 0})));  // black
  AdaptiveSampler shape(4, 32, AdaptiveMethod::ShapeId, 1);
  EXPECT_FALSE(shape.needsMoreSamples(results({0, 5, 0, 9}, {7, 7, 7, 7})));
  EXPECT_FALSE(shape.needsMoreSamples(results({0, 5, 0, 9}, {0, 0, 0, 0})));
  EXPECT_TRUE(shape.needsMoreSamples(results({1, 1, 1, 1}, {7, 7, 0, 7})));
  EXPECT_TRUE(shape.needsMoreSamples(results({1, 1, 1, 1}, {7, 7, 7, 8})));
  // Non-adaptive samplers never ask for more and start with all their samples.
  auto strat = createSampler("stratified", ParamSet(), 1, 0, FileLoc{});
  EXPECT_EQ(strat->initialSamplesPerPixel(), strat->samplesPerPixel());
  EXPECT_FALSE(strat->needsMoreSamples(results({0, 9}, {1, 2})));
}

TEST(AdaptiveSampler, InitialAndAllSamplesAreEachNets) {
  AdaptiveSampler sampler(4, 16, AdaptiveMethod::Contrast, 12);
  for (int n : {4, 16}) {
    std::vector<int> count(size_t(n), 0);
    for (int s = 0; s < n; ++s) {
      sampler.startPixelSample({9, 2}, s);
      Point2f p = sampler.getPixel2D();
      // The square elementary intervals (2 x 2 for 4 points, 4 x 4 for 16).
      int side = n == 4 ? 2 : 4;
      ++count[size_t(int(p.y * side) * side + int(p.x * side))];
    }
    for (int c : count) EXPECT_EQ(c, 1) << n;
  }
}

}  // namespace
}  // namespace candela
