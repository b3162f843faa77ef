// Noise-driven adaptive sampling (--noise-threshold): the pass schedule, that pixels stop where
// and only where their own noise estimate allows, the same bits for any thread count, tile size
// and crop window, and that the estimate it stops on is calibrated against a reference.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>
#include <vector>

#include "film/error_metrics.h"
#include "integrators/adaptive_render.h"
#include "support/render_scene.h"

namespace candela {
namespace {

// The Cornell box at res x res with independent samples (the random sampler; the variance
// estimate is that of independent samples) and the box filter.
std::string randomBox(int res) {
  std::string s = test::cornellBoxText(res);
  auto replace = [&](const std::string& from, const std::string& to) {
    size_t at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) s.replace(at, from.size(), to);
  };
  replace("Sampler \"stratified\" \"integer xsamples\" [8] \"integer ysamples\" [8]",
          "Sampler \"random\"");
  replace("PixelFilter \"gaussian\"", "PixelFilter \"box\"");
  return s;
}

struct AdaptiveRender {
  test::RenderedScene built;
  ProgressiveResult result;
  const Film& film() const { return built.film(); }
};

AdaptiveRender renderAdaptively(const std::string& text, int spp, uint64_t seed, double threshold,
                                int minSamples = 0, int threads = 0, int tile = 16,
                                std::optional<Bounds2f> crop = std::nullopt) {
  BuildOptions b;
  b.sppOverride = spp;
  b.seed = seed;
  b.cropWindow = crop;
  AdaptiveRender r{test::buildSceneText(text, b), {}};
  ProgressiveOptions po;
  po.render = RenderOptions{threads, tile, true};
  po.adaptive.noiseThreshold = threshold;
  po.adaptive.minSamples = minSamples;
  r.result = renderJob(r.built.job(), po);
  return r;
}

TEST(AdaptiveSampling, PassEndsStartAtTheMinimumAndGrowByGroupsToTheSampleCount) {
  for (int spp : {1, 7, 16, 17, 64, 100, 1024, 4096})
    for (int minSamples : {0, 1, 4, 16, 24, 5000}) {
      AdaptiveSampling a{0.1, minSamples};
      std::vector<int> ends = adaptivePassEnds(spp, a);
      ASSERT_FALSE(ends.empty());
      const int first = std::min(spp, minSamples > 0 ? minSamples : 16);
      EXPECT_EQ(ends.front(), first) << spp << " " << minSamples;
      EXPECT_EQ(ends.back(), spp);
      for (size_t i = 1; i < ends.size(); ++i) {
        const int step = ends[i] - ends[i - 1];
        EXPECT_GT(step, 0);
        // Whole groups of eight except the last, and at most about an eighth of the count so
        // far once that exceeds the minimum's step.
        if (ends[i] < spp) {
          EXPECT_EQ(step % 8, 0) << spp << " " << minSamples << " " << i;
        }
        EXPECT_LE(step, std::max((first + 7) / 8 * 8, (ends[i - 1] / 8 + 7) / 8 * 8));
      }
      // A few dozen passes even for thousands of samples (4096: 42).
      EXPECT_LE(ends.size(), 48u) << spp;
    }
}

TEST(AdaptiveSampling, PixelsStopExactlyWhenTheirNoiseEstimateMeetsTheThreshold) {
  const double threshold = 0.08;
  const int spp = 256, minSamples = 16;
  AdaptiveRender r = renderAdaptively(randomBox(24), spp, 3, threshold, minSamples);
  const std::vector<int> ends = adaptivePassEnds(spp, AdaptiveSampling{threshold, minSamples});
  const Film& film = r.film();
  const Bounds2i b = film.pixelBounds();
  int stoppedEarly = 0, full = 0;
  for (int y = b.pMin.y; y < b.pMax.y; ++y)
    for (int x = b.pMin.x; x < b.pMax.x; ++x) {
      Point2i p(x, y);
      const long n = film.pixelSampleCount(p);
      // Every pixel ends on a pass boundary ...
      ASSERT_NE(std::find(ends.begin(), ends.end(), int(n)), ends.end()) << n;
      // ... below the threshold if it stopped before the end ...
      const double noise2 = estimatePixelRelMse(film, p);
      if (n < spp) {
        ++stoppedEarly;
        EXPECT_LE(noise2, threshold * threshold) << x << "," << y << " at " << n;
      } else {
        ++full;
      }
    }
  // ... and the threshold is one that some pixels meet early and some do not.
  EXPECT_GT(stoppedEarly, 0);
  EXPECT_GT(full, 0);
  EXPECT_EQ(r.result.spp, spp);
  EXPECT_LT(r.result.total.samples, uint64_t(spp) * b.area());
  EXPECT_EQ(r.result.total.samples, [&] {
    uint64_t sum = 0;
    for (int y = b.pMin.y; y < b.pMax.y; ++y)
      for (int x = b.pMin.x; x < b.pMax.x; ++x) sum += film.pixelSampleCount(Point2i(x, y));
    return sum;
  }());
}

// A pixel stops at the second check in a row that finds it at the threshold: with one every
// pixel meets, at the minimum (8) and the next check (16).
TEST(AdaptiveSampling, AHighThresholdStopsEveryPixelAtTheSecondCheck) {
  AdaptiveRender r = renderAdaptively(randomBox(16), 256, 5, 1e6, 8);
  EXPECT_EQ(r.result.reason, StopReason::NoiseThreshold);
  EXPECT_EQ(r.result.passes, 2);
  EXPECT_EQ(r.result.total.samples, uint64_t(16 * 16 * 16));
}

// With path guiding, every pixel takes the training passes (1, 2, ..., 64 of 256 samples) and
// is judged from their end on, though the minimum is 8: a threshold every pixel meets then
// stops them all at the second check, 128, and a lower one leaves each on a pass boundary at or
// past it.
TEST(AdaptiveSampling, WithGuidingPixelsAreJudgedFromTheEndOfTraining) {
  std::string text = randomBox(16);
  const std::string path = "SurfaceIntegrator \"path\" \"integer maxdepth\" [5]";
  ASSERT_NE(text.find(path), std::string::npos);
  text.replace(text.find(path), path.size(), path + " \"bool guiding\" \"true\"");
  AdaptiveRender high = renderAdaptively(text, 256, 5, 1e6, 8);
  EXPECT_EQ(high.result.reason, StopReason::NoiseThreshold);
  EXPECT_EQ(high.result.total.samples, uint64_t(128 * 16 * 16));
  AdaptiveRender low = renderAdaptively(text, 256, 5, 0.1, 8);
  std::vector<int> ends = adaptivePassEnds(256, AdaptiveSampling{0.1, 64});
  const Bounds2i b = low.film().pixelBounds();
  int stoppedEarly = 0;
  for (int y = b.pMin.y; y < b.pMax.y; ++y)
    for (int x = b.pMin.x; x < b.pMax.x; ++x) {
      const long n = low.film().pixelSampleCount(Point2i(x, y));
      ASSERT_NE(std::find(ends.begin(), ends.end(), int(n)), ends.end()) << n;
      stoppedEarly += n < 256;
    }
  EXPECT_GT(stoppedEarly, 0);
}

TEST(AdaptiveSampling, IntegratorsWhosePixelsDoNotHoldTheirLightAreRefused) {
  for (const char* integrator : {"SurfaceIntegrator \"bdpt\" \"integer maxdepth\" [3]",
                                 "SurfaceIntegrator \"sppm\" \"float radius\" [8]"}) {
    std::string text = test::cornellBoxText(8, integrator);
    try {
      renderAdaptively(text, 16, 1, 0.1);
      ADD_FAILURE() << integrator << " rendered adaptively";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("its own samples"), std::string::npos) << e.what();
    }
  }
}

bool sameBits(const Film& a, const Film& b) {
  ImageBuffer ia = a.image(), ib = b.image();
  return ia.data.size() == ib.data.size() &&
         std::memcmp(ia.data.data(), ib.data.data(), ia.data.size() * sizeof(float)) == 0;
}

TEST(AdaptiveSampling, SameBitsForAnyThreadCountTileSizeAndCropWindow) {
  const std::string text = randomBox(32);
  AdaptiveRender one = renderAdaptively(text, 128, 7, 0.1, 8, 1, 16);
  AdaptiveRender two = renderAdaptively(text, 128, 7, 0.1, 8, 2, 5);
  EXPECT_TRUE(sameBits(one.film(), two.film()));
  EXPECT_EQ(one.result.total.samples, two.result.total.samples);
  // A crop window's pixels are the full render's, samples and all.
  AdaptiveRender crop = renderAdaptively(text, 128, 7, 0.1, 8, 2, 16,
                                         Bounds2f(Point2f(0.25f, 0.5f), Point2f(0.75f, 1)));
  const Bounds2i cb = crop.film().pixelBounds();
  ASSERT_GT(cb.area(), 0);
  for (int y = cb.pMin.y; y < cb.pMax.y; ++y)
    for (int x = cb.pMin.x; x < cb.pMax.x; ++x) {
      Point2i p(x, y);
      ASSERT_EQ(crop.film().pixelSampleCount(p), one.film().pixelSampleCount(p));
      Spectrum a = crop.film().pixelValue(p), c = one.film().pixelValue(p);
      for (int k = 0; k < 3; ++k) ASSERT_EQ(a[k], c[k]) << x << "," << y;
    }
}

// The estimate a pixel stops on against its real error (the reference: 4096 spp of another
// seed). A pixel stops at the second check in a row where its estimated squared relative error
// is at most t^2, so the stopped pixels' estimates average below t^2. Stopping on a low estimate
// favours pixels whose estimate happens to be low, so their real error runs above their
// estimate: over seeds 1-24 (Cornell box 32 x 32, random sampler, t = 0.1, minimum 16, up to
// 512 spp) the stopped pixels' (about 1,013 of 1,024) mean estimate was 0.0033 and their mean
// real squared error 0.0042 (sd 0.00053, at most 0.0057), and 99.4% of them (sd 0.25%, at least
// 98.9%) were within 2t of the reference. The test asserts per seed that the real error stays
// below 0.75 t^2 (6.1 sd above the mean) and that at least 97% are within 2t (9.6 sd below): no
// seed of 24 came near either. Stopping at the first check that meets the threshold, as
// candela did before, gave 0.0074 (at most 0.0099) and 97.9% (at least 97.0%) and fails both
// for some seeds; an estimate too low by a factor of 4 fails both. CI runs the first kSeeds.
TEST(AdaptiveSampling, TheStoppingEstimateIsCalibratedAgainstAReference) {
  constexpr int kSeeds = 4;
  const int res = 32;
  const std::string text = randomBox(res);
  BuildOptions rb;
  rb.sppOverride = 4096;
  rb.seed = 1000;
  test::RenderedScene ref = test::buildSceneText(text, rb);
  test::PixelPasses(ref.job()).render(*ref.job().scene, *ref.job().film,
                                      RenderOptions{0, 16, true});
  const Film& rf = ref.film();
  const double t = 0.1;
  for (uint64_t seed = 1; seed <= kSeeds; ++seed) {
    AdaptiveRender r = renderAdaptively(text, 512, seed, t, 16);
    const Film& f = r.film();
    const Bounds2i b = f.pixelBounds();
    double real = 0, estimated = 0;
    int stopped = 0, within = 0;
    for (int y = b.pMin.y; y < b.pMax.y; ++y)
      for (int x = b.pMin.x; x < b.pMax.x; ++x) {
        Point2i p(x, y);
        if (f.pixelSampleCount(p) >= 512) continue;
        Spectrum v = f.pixelValue(p), w = rf.pixelValue(p);
        double e2 = 0;
        for (int c = 0; c < 3; ++c) {
          double d = double(v[c]) - w[c];
          e2 += d * d / (double(w[c]) * w[c] + kRelMseEpsilon) / 3;
        }
        real += e2;
        estimated += estimatePixelRelMse(f, p);
        ++stopped;
        within += e2 <= 4 * t * t;
      }
    ASSERT_GT(stopped, res * res / 2);
    real /= stopped;
    estimated /= stopped;
    std::printf("seed %2d stopped %4d real %.5f estimated %.5f within 2t %.3f\n", int(seed),
                stopped, real, estimated, double(within) / stopped);
    EXPECT_LE(estimated, t * t);
    EXPECT_LE(real, 0.75 * t * t) << "seed " << seed;
    EXPECT_GE(double(within) / stopped, 0.97) << "seed " << seed;
  }
}

}  // namespace
}  // namespace candela
