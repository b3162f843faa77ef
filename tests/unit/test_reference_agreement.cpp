// The conformance comparison's statistic (support/reference_agreement.h) on synthetic images whose
// noise is known: calibrated when render and reference agree, sensitive when they do not.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "support/reference_agreement.h"
#include "support/tail_probabilities.h"

namespace candela::test {
namespace {

// F critical values from standard tables (4 digits).
TEST(ReferenceAgreement, FSurvivalMatchesTables) {
  EXPECT_NEAR(fSurvival(2.9782, 10, 10), 0.05, 0.003);
  EXPECT_NEAR(fSurvival(2.1242, 20, 20), 0.05, 0.002);
  EXPECT_NEAR(fSurvival(2.9377, 20, 20), 0.01, 0.0005);
  EXPECT_EQ(fSurvival(0, 10, 10), 1);
  EXPECT_EQ(fSurvival(INFINITY, 10, 10), 0);
  EXPECT_NEAR(fSurvival(1, 200, 200), 0.5, 1e-3);
}

struct Synthetic {
  std::vector<ImageBuffer> renders;
  ImageBuffer reference;
  std::vector<const ImageBuffer*> all() const {
    std::vector<const ImageBuffer*> out;
    for (const ImageBuffer& r : renders) out.push_back(&r);
    return out;
  }
};

// A smooth image plus per-pixel Gaussian noise whose deviation is sigma(x, y) at n samples per
// pixel (the reference: at 1024), and `bias` added to the renders in the top-left region; `count`
// renders.
template <typename Sigma>
Synthetic makeImages(uint32_t seed, Sigma sigma, double bias = 0, int count = 2) {
  const int size = 64, n = 16, referenceN = 1024;
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  Synthetic s{std::vector<ImageBuffer>(count, ImageBuffer(size, size, {"R", "G", "B"})),
              ImageBuffer(size, size, {"R", "G", "B"})};
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      for (int c = 0; c < 3; ++c) {
        const double truth = 1 + 0.5 * std::sin(0.1 * x + c) * std::cos(0.07 * y);
        const double sd = sigma(x, y);
        const double shift = (x < 16 && y < 16) ? bias : 0;
        for (ImageBuffer& r : s.renders) r.at(x, y, c) = float(truth + shift + sd * normal(rng));
        s.reference.at(x, y, c) =
            float(truth + sd * std::sqrt(double(n) / referenceN) * normal(rng));
      }
  return s;
}

ReferenceAgreementOptions options() {
  ReferenceAgreementOptions o;
  o.samplesPerPixel = 16;
  o.referenceSamplesPerPixel = 1024;
  o.referenceIsHalf = false;
  o.resolution = 0;
  return o;
}

// Over 40 agreeing image triples (1920 regions), the fraction of p-values below 0.05 is within
// the binomial 99.9% interval around 0.05 (about 0.034-0.069), widened for the approximations to
// 0.025-0.08; likewise below 0.5.
template <typename Sigma>
void expectCalibrated(Sigma sigma, int renders = 2) {
  int below5 = 0, below50 = 0, total = 0;
  for (uint32_t seed = 1; seed <= 40; ++seed) {
    Synthetic s = makeImages(seed, sigma, 0, renders);
    for (const ReferenceRegion& r : compareWithReference(s.all(), s.reference, options()).regions) {
      below5 += r.pValue < 0.05;
      below50 += r.pValue < 0.5;
      ++total;
    }
  }
  EXPECT_GT(double(below5) / total, 0.025);
  EXPECT_LT(double(below5) / total, 0.08);
  EXPECT_GT(double(below50) / total, 0.44);
  EXPECT_LT(double(below50) / total, 0.56);
}

TEST(ReferenceAgreement, CalibratedForEvenNoise) {
  expectCalibrated([](int, int) { return 0.2; });
}

TEST(ReferenceAgreement, CalibratedWhenAFewBlocksCarryMostNoise) {
  // Every eighth column of blocks 30 times noisier: Satterthwaite's degrees of freedom drop.
  expectCalibrated([](int x, int) { return (x / 4) % 8 == 0 ? 3.0 : 0.1; });
}

TEST(ReferenceAgreement, CalibratedWithFourRenders) {
  expectCalibrated([](int, int) { return 0.2; }, 4);
  expectCalibrated([](int x, int) { return (x / 4) % 8 == 0 ? 3.0 : 0.1; }, 4);
}

TEST(ReferenceAgreement, TwoRendersGiveTheTwoRenderStatistic) {
  // With K = 2 the variance estimate is (a - b)^2 / 4 and both degrees of freedom are
  // 3 (sum d)^2 / sum d^2: computed here by hand for one region.
  Synthetic s = makeImages(9, [](int x, int) { return (x / 4) % 8 == 0 ? 3.0 : 0.1; });
  ReferenceAgreementOptions o = options();
  ReferenceAgreement agreement = compareWithReference(s.all(), s.reference, o);
  const ReferenceRegion& r = agreement.regions.front();  // region (0, 0), channel R
  double sum = 0, squares = 0, numerator = 0;
  const double share = 1 + 2.0 * o.samplesPerPixel / o.referenceSamplesPerPixel;
  for (int by = 0; by < 4; ++by)
    for (int bx = 0; bx < 4; ++bx) {
      double ma = 0, mb = 0, mr = 0;
      for (int y = 4 * by; y < 4 * by + 4; ++y)
        for (int x = 4 * bx; x < 4 * bx + 4; ++x) {
          ma += s.renders[0].at(x, y, 0) / 16.0;
          mb += s.renders[1].at(x, y, 0) / 16.0;
          mr += s.reference.at(x, y, 0) / 16.0;
        }
      const double d = (ma - mb) * (ma - mb) / 4 * share;
      sum += d;
      squares += d * d;
      numerator += ((ma + mb) / 2 - mr) * ((ma + mb) / 2 - mr);
    }
  EXPECT_NEAR(r.ratio, numerator / sum, 1e-9 * r.ratio);
  EXPECT_NEAR(r.degreesOfFreedom, std::min(16.0, 3 * sum * sum / squares), 1e-9);
  EXPECT_EQ(r.denominatorDegreesOfFreedom, r.degreesOfFreedom);
}

TEST(ReferenceAgreement, FourRendersFindHalfTheBiasTwoFind) {
  // Four renders' mean has half the variance of two: a bias that two renders leave below the
  // conformance level in the top-left region (0.08, 1.6 block deviations) is found with four.
  auto worstTopLeft = [](int renders) {
    Synthetic s = makeImages(
        13, [](int, int) { return 0.2; }, 0.08, renders);
    ReferenceAgreement agreement = compareWithReference(s.all(), s.reference, options());
    double p = 1;
    for (const ReferenceRegion& r : agreement.regions)
      if (r.regionX == 0 && r.regionY == 0) p = std::min(p, r.pValue);
    return p;
  };
  const double level = stats::sidak(0.001, 48);
  EXPECT_GT(worstTopLeft(2), level);
  EXPECT_LT(worstTopLeft(4), level);
}

TEST(ReferenceAgreement, OneRenderIsRefused) {
  Synthetic s = makeImages(
      1, [](int, int) { return 0.2; }, 0, 1);
  EXPECT_THROW(compareWithReference(s.all(), s.reference, options()), std::invalid_argument);
}

TEST(ReferenceAgreement, FindsABiasOfThreeTimesTheBlockNoiseInOneRegion) {
  // Block means of one render have deviation 0.2 / 4 = 0.05; a bias of 0.15 (15% of the image)
  // in the top-left region (16 blocks) is found there, at the conformance test's level, and
  // nowhere else.
  Synthetic s = makeImages(
      7, [](int, int) { return 0.2; }, 0.15);
  ReferenceAgreement agreement = compareWithReference(s.all(), s.reference, options());
  const double level = stats::sidak(0.001, int(agreement.regions.size()));
  for (const ReferenceRegion& r : agreement.regions) {
    if (r.regionX == 0 && r.regionY == 0)
      EXPECT_LT(r.pValue, level) << agreement.describe(r);
    else
      EXPECT_GT(r.pValue, level) << agreement.describe(r);
  }
}

TEST(ReferenceAgreement, NoiselessDifferencesFailAndNoiselessAgreementPasses) {
  Synthetic s = makeImages(3, [](int, int) { return 0.0; });
  for (const ReferenceRegion& r : compareWithReference(s.all(), s.reference, options()).regions)
    EXPECT_EQ(r.pValue, 1);
  s.reference.at(5, 5, 1) += 0.01f;
  ReferenceAgreement agreement = compareWithReference(s.all(), s.reference, options());
  EXPECT_EQ(agreement.worst().pValue, 0);
  EXPECT_EQ(agreement.worst().channel, 1);
}

TEST(ReferenceAgreement, ExcludedBlocksAreLeftOutAndTheRestOfTheirRegionCompared) {
  // A noiseless render; the reference differs in pixel (5, 5), block (1, 1) of region (0, 0).
  Synthetic s = makeImages(13, [](int, int) { return 0.0; });
  s.reference.at(5, 5, 1) += 0.01f;
  ReferenceAgreementOptions o = options();
  EXPECT_EQ(compareWithReference(s.all(), s.reference, o).worst().pValue, 0);
  // Left out, its block no longer counts; the region's other 15 blocks agree.
  o.excludedBlocks = {{1, 1}};
  ReferenceAgreement agreement = compareWithReference(s.all(), s.reference, o);
  EXPECT_EQ(agreement.worst().pValue, 1);
  EXPECT_EQ(agreement.relMse, 0);
  // A difference elsewhere in that region is still found.
  s.reference.at(9, 2, 0) += 0.01f;
  agreement = compareWithReference(s.all(), s.reference, o);
  EXPECT_EQ(agreement.worst().pValue, 0);
  EXPECT_EQ(agreement.worst().regionX, 0);
  EXPECT_EQ(agreement.worst().regionY, 0);
  // A region with no block left is refused.
  for (int by = 0; by < 4; ++by)
    for (int bx = 0; bx < 4; ++bx) o.excludedBlocks.insert({bx, by});
  EXPECT_THROW(compareWithReference(s.all(), s.reference, o), std::invalid_argument);
}

TEST(ReferenceAgreement, DifferencesBelowTheResolutionAreNotCounted) {
  // A noiseless render; the reference 0.05% brighter in one block: a difference at resolution 0,
  // none at the default 1e-3 of the region's mean; 3% in one block of the region's 16 is found
  // (F = 0.03^2 / (16 x 0.001^2) = 56).
  Synthetic s = makeImages(11, [](int, int) { return 0.0; });
  ReferenceAgreementOptions o = options();
  auto brighten = [&](float factor) {
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 4; ++x) s.reference.at(x, y, 0) *= factor;
  };
  brighten(1.0005f);
  EXPECT_EQ(compareWithReference(s.all(), s.reference, o).worst().pValue, 0);
  o.resolution = 1e-3;
  EXPECT_GT(compareWithReference(s.all(), s.reference, o).worst().pValue, 0.01);
  brighten(1.03f / 1.0005f);
  EXPECT_LT(compareWithReference(s.all(), s.reference, o).worst().pValue, 1e-6);
}

TEST(ReferenceAgreement, HalfFloatRoundingOfTheReferenceIsNoise) {
  // A noiseless render against its own reference rounded to 11 significant bits: no difference
  // when the reference is declared half, a difference otherwise.
  Synthetic s = makeImages(5, [](int, int) { return 0.0; });
  for (float& v : s.reference.data) {
    int e;
    std::frexp(v, &e);
    const float step = std::ldexp(1.f, e - 11);
    v = std::round(v / step) * step;
  }
  ReferenceAgreementOptions o = options();
  EXPECT_EQ(compareWithReference(s.all(), s.reference, o).worst().pValue, 0);
  o.referenceIsHalf = true;
  EXPECT_GT(compareWithReference(s.all(), s.reference, o).worst().pValue, stats::sidak(0.001, 48));
}

}  // namespace
}  // namespace candela::test
