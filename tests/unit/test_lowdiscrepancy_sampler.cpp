// The (0,2)-sequence and the low-discrepancy sampler: radical inverse values, the net property
// (one point in every elementary interval, for every shape), per pixel and per dimension, for the
// whole pixel and for its first 2^j samples; scrambling and the random pairing of dimensions.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "samplers/lowdiscrepancy_sampler.h"
#include "samplers/radical_inverse.h"
#include "samplers/zero_two_sequence.h"

namespace candela {
namespace {

// Whether 2^k points put exactly one point in every elementary interval of volume 2^-k:
// [a/2^i, (a+1)/2^i) x [b/2^(k-i), (b+1)/2^(k-i)) for every i in [0, k]. Returns the first
// failing shape's i, or -1.
int failingIntervalShape(const std::vector<Point2f>& points, int k) {
  if (points.size() != (size_t(1) << k)) return 0;
  for (int i = 0; i <= k; ++i) {
    int nx = 1 << i, ny = 1 << (k - i);
    std::vector<int> count(size_t(nx) * ny, 0);
    for (Point2f p : points) {
      if (!(p.x >= 0 && p.x < 1 && p.y >= 0 && p.y < 1)) return i;
      // Multiplying by a power of two is exact, so the interval is exact too.
      ++count[size_t(int(p.y * Float(ny))) * nx + size_t(int(p.x * Float(nx)))];
    }
    for (int c : count)
      if (c != 1) return i;
  }
  return -1;
}

bool oneValuePerInterval(const std::vector<Float>& values) {
  size_t n = values.size();
  std::vector<int> count(n, 0);
  for (Float v : values) {
    if (!(v >= 0 && v < 1)) return false;
    ++count[size_t(v * Float(n))];
  }
  for (int c : count)
    if (c != 1) return false;
  return true;
}

TEST(RadicalInverse, BaseTwoValues) {
  // lrt draft Fig. 7.20.
  const Float expected[] = {0.5f, 0.25f, 0.75f, 0.125f, 0.625f};
  for (uint32_t n = 1; n <= 5; ++n) {
    EXPECT_EQ(radicalInverse(n, 2), expected[n - 1]) << n;
    EXPECT_EQ(bitsToUnitFloat(vanDerCorputBits(n, 0)), expected[n - 1]) << n;
  }
  EXPECT_EQ(radicalInverse(0, 2), 0.f);
  // Base 3: 1 -> 1/3, 2 -> 2/3, 3 = 10_3 -> 1/9, 5 = 12_3 -> 2/3 + 1/9... mirrored: 0.21_3 = 7/9.
  EXPECT_FLOAT_EQ(radicalInverse(1, 3), 1.f / 3);
  EXPECT_FLOAT_EQ(radicalInverse(2, 3), 2.f / 3);
  EXPECT_FLOAT_EQ(radicalInverse(3, 3), 1.f / 9);
  EXPECT_FLOAT_EQ(radicalInverse(5, 3), 7.f / 9);
  // Van der Corput in bits equals the generic base-2 radical inverse.
  for (uint32_t n = 0; n < 5000; n += 7)
    ASSERT_EQ(bitsToUnitFloat(vanDerCorputBits(n, 0)), radicalInverse(n, 2)) << n;
  EXPECT_EQ(kPrimes[0], 2u);
  EXPECT_EQ(kPrimes[5], 13u);
  EXPECT_EQ(kPrimes[kPrimeTableSize - 1], 8161u);
}

TEST(ZeroTwoSequence, SobolSecondDimensionValues) {
  // Generator columns 1, 11, 101, 1111 (binary fractions): n = 1..5 -> .5, .75, .25, .625, .125.
  const Float expected[] = {0.5f, 0.75f, 0.25f, 0.625f, 0.125f};
  for (uint32_t n = 1; n <= 5; ++n) EXPECT_EQ(bitsToUnitFloat(sobol2Bits(n, 0)), expected[n - 1]);
  EXPECT_EQ(reverseBits32(1), 0x80000000u);
  EXPECT_EQ(reverseBits32(0x12345678u), 0x1e6a2c48u);
}

TEST(ZeroTwoSequence, EveryAlignedBlockIsANetScrambledOrNot) {
  for (uint32_t scramble : {0u, 0x9e3779b9u, 0xffffffffu})
    for (int k = 0; k <= 10; ++k)
      for (uint32_t block : {0u, 1u, 5u}) {
        std::vector<Point2f> pts;
        for (uint32_t i = 0; i < (1u << k); ++i) {
          uint32_t n = (block << k) + i;
          pts.emplace_back(bitsToUnitFloat(vanDerCorputBits(n, scramble)),
                           bitsToUnitFloat(sobol2Bits(n, ~scramble)));
        }
        ASSERT_EQ(failingIntervalShape(pts, k), -1)
            << "k " << k << " block " << block << " scramble " << scramble;
      }
}

TEST(ZeroTwoSequence, NestedPermutationKeepsAlignedBlocks) {
  for (uint64_t key : {1ull, 0xdeadbeefull, 77777ull}) {
    const int k = 6;
    std::vector<int> seen(64, 0);
    for (uint32_t i = 0; i < 64; ++i) {
      uint32_t p = nestedIndexPermutation(i, k, key);
      ASSERT_LT(p, 64u);
      ++seen[p];
      // Indices in one aligned block of 2^j land in one aligned block of 2^j.
      for (int j = 1; j <= k; ++j) {
        uint32_t first = nestedIndexPermutation(i & ~((1u << j) - 1), k, key);
        ASSERT_EQ(p >> j, first >> j) << "i " << i << " j " << j;
      }
    }
    for (int c : seen) ASSERT_EQ(c, 1);
    // Higher bits pass through.
    EXPECT_EQ(nestedIndexPermutation(64 * 3 + 5, k, key) >> k, 3u);
  }
  // It does permute.
  int moved = 0;
  for (uint32_t i = 0; i < 64; ++i) moved += nestedIndexPermutation(i, 6, 42) != i;
  EXPECT_GT(moved, 16);
}

TEST(LowDiscrepancySampler, EveryDimensionOfAPixelIsANet) {
  for (int k = 0; k <= 8; ++k) {
    const int spp = 1 << k;
    LowDiscrepancySampler sampler(spp, 1234);
    for (Point2i pixel : {Point2i(0, 0), Point2i(17, 3), Point2i(-5, 900)}) {
      const int kDims = 6;  // alternating 1D and 2D after the image plane
      std::vector<Point2f> image;
      std::vector<std::vector<Point2f>> twoD(kDims);
      std::vector<std::vector<Float>> oneD(kDims);
      for (int s = 0; s < spp; ++s) {
        sampler.startPixelSample(pixel, s);
        image.push_back(sampler.getPixel2D());
        for (int d = 0; d < kDims; ++d) {
          if (d % 2 == 0)
            oneD[d].push_back(sampler.get1D());
          else
            twoD[d].push_back(sampler.get2D());
        }
      }
      ASSERT_EQ(failingIntervalShape(image, k), -1) << "spp " << spp;
      for (int d = 0; d < kDims; ++d) {
        if (d % 2 == 0)
          ASSERT_TRUE(oneValuePerInterval(oneD[d])) << "spp " << spp << " dim " << d;
        else
          ASSERT_EQ(failingIntervalShape(twoD[d], k), -1) << "spp " << spp << " dim " << d;
      }
    }
  }
}

TEST(LowDiscrepancySampler, FirstPowerOfTwoSamplesAndLaterRoundsAreNetsToo) {
  // Progressive and adaptive rendering take a pixel's samples in prefixes.
  const int spp = 64;
  LowDiscrepancySampler sampler(spp, 5);
  Point2i pixel(8, 9);
  for (int j = 0; j <= 6; ++j) {
    std::vector<Point2f> image, dim1;
    for (int s = 0; s < (1 << j); ++s) {
      sampler.startPixelSample(pixel, s);
      image.push_back(sampler.getPixel2D());
      sampler.get1D();
      dim1.push_back(sampler.get2D());
    }
    EXPECT_EQ(failingIntervalShape(image, j), -1) << j;
    EXPECT_EQ(failingIntervalShape(dim1, j), -1) << j;
  }
  // Samples [spp, 2 spp): a second round, again a net.
  std::vector<Point2f> second;
  for (int s = spp; s < 2 * spp; ++s) {
    sampler.startPixelSample(pixel, s);
    second.push_back(sampler.getPixel2D());
  }
  EXPECT_EQ(failingIntervalShape(second, 6), -1);
}

TEST(LowDiscrepancySampler, ScrambledPerPixelAndDimensionsPairedAtRandom) {
  const int spp = 16;
  LowDiscrepancySampler sampler(spp, 99);
  auto pixelPoints = [&](Point2i p) {
    std::vector<Float> v;
    for (int s = 0; s < spp; ++s) {
      sampler.startPixelSample(p, s);
      Point2f q = sampler.getPixel2D();
      v.push_back(q.x);
      v.push_back(q.y);
    }
    return v;
  };
  EXPECT_NE(pixelPoints({0, 0}), pixelPoints({1, 0}));
  EXPECT_NE(pixelPoints({0, 0}), pixelPoints({0, 1}));
  // Pairing: without the per-dimension permutation, two 1D dimensions of a pixel would be
  // related by a fixed XOR (for some pixels the identity). Their correlation over 4000 pixels
  // x 16 samples is ~N(0, 1/64000), so |r| < 0.03 is about 7.5 standard deviations.
  double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
  int n = 0;
  for (int px = 0; px < 4000; ++px)
    for (int s = 0; s < spp; ++s) {
      sampler.startPixelSample({px, 7}, s);
      double a = sampler.get1D(), b = sampler.get1D();
      sx += a;
      sy += b;
      sxx += a * a;
      syy += b * b;
      sxy += a * b;
      ++n;
    }
  double cov = sxy / n - sx / n * sy / n;
  double r = cov / std::sqrt((sxx / n - sx / n * sx / n) * (syy / n - sy / n * sy / n));
  EXPECT_LT(std::abs(r), 0.03);
  // And the values of two dimensions of one sample are not the same pattern.
  int equal = 0;
  for (int s = 0; s < spp; ++s) {
    sampler.startPixelSample({3, 3}, s);
    equal += sampler.get1D() == sampler.get1D();
  }
  EXPECT_LT(equal, spp);
}

}  // namespace
}  // namespace candela
