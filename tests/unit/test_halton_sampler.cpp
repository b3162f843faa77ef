// The Halton sampler: values in [0, 1); the first b^m samples stratified in base b per
// coordinate and the first 2^a 3^b image samples one per cell of a 2^a x 3^b grid, scrambled or
// not; scrambling differs per pixel and keeps the digit structure. The fast evaluation (tables per
// pixel and coordinate) gives the reference scrambledRadicalInverse's values bit for bit, in any
// order of pixels and samples.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "samplers/halton_sampler.h"
#include "samplers/radical_inverse.h"

namespace candela {
namespace {

int ipow(int b, int e) {
  int r = 1;
  while (e-- > 0) r *= b;
  return r;
}

bool onePerCell(const std::vector<Point2f>& pts, int nx, int ny) {
  std::vector<int> count(size_t(nx) * ny, 0);
  for (Point2f p : pts) {
    if (!(p.x >= 0 && p.x < 1 && p.y >= 0 && p.y < 1)) return false;
    int cx = std::min(int(double(p.x) * nx), nx - 1), cy = std::min(int(double(p.y) * ny), ny - 1);
    ++count[size_t(cy) * nx + cx];
  }
  for (int c : count)
    if (c != 1) return false;
  return true;
}

TEST(ScrambledRadicalInverse, StratifiedInEveryBaseAndKeyDependent) {
  for (uint32_t base : {2u, 3u, 5u, 7u, 31u}) {
    for (uint64_t key : {1ull, 12345ull}) {
      int m = base <= 3 ? 5 : 2;
      int n = ipow(int(base), m);
      std::vector<int> count(size_t(n), 0);
      for (int i = 0; i < n; ++i) {
        Float v = scrambledRadicalInverse(uint32_t(i), base, key);
        ASSERT_GE(v, 0.f);
        ASSERT_LT(v, 1.f);
        ++count[size_t(double(v) * n)];
      }
      for (int c : count) ASSERT_EQ(c, 1) << "base " << base;
    }
    EXPECT_NE(scrambledRadicalInverse(7, base, 1), scrambledRadicalInverse(7, base, 2));
  }
}

TEST(ScrambledRadicalInverse, ScramblesEveryDigitOfTheExpansion) {
  // Phi_b(0) scrambled is sum c_i b^-(i+1) over the D digits: its digits are the offsets, which
  // differ from key to key in every position, so across keys each of the first digits takes
  // every value (here: the first 4 base-5 digits of 200 keys' values at n = 0).
  for (int digit = 0; digit < 4; ++digit) {
    std::vector<int> seen(5, 0);
    for (uint64_t key = 0; key < 200; ++key) {
      double v = scrambledRadicalInverse(0, 5, key);
      for (int i = 0; i < digit; ++i) v = v * 5 - std::floor(v * 5);
      ++seen[size_t(std::floor(v * 5))];
    }
    for (int c : seen) EXPECT_GT(c, 15) << "digit " << digit;
  }
}

TEST(FastScrambledRadicalInverse, SameBitsAsTheReference) {
  // Below the count by the tables, past it (and past b^D for base 2) by the general path; 4096,
  // the most the sampler tabulates, puts a_0 n + c_0 near its largest (2^25 for base 8161).
  std::vector<uint64_t> table;
  for (uint32_t base : {2u, 3u, 5u, 7u, 31u, 257u, 8161u})
    for (uint32_t count : {1u, 2u, 7u, 64u, 100u, 1000u, 4096u}) {
      FastScrambledRadicalInverse fast(base, count);
      ASSERT_EQ(fast.tableSize(), (count + base - 1) / base);
      table.assign(fast.tableSize(), 0);
      for (uint64_t key : {3ull, 0x9e3779b97f4a7c15ull}) {
        fast.setKey(key, table.data());
        for (uint32_t n = 0; n < 2 * count + base; ++n)
          ASSERT_EQ(fast.value(n, table.data()), scrambledRadicalInverse(n, base, key))
              << "base " << base << " count " << count << " n " << n;
        for (uint32_t n : {1u << 26, (1u << 26) + 12345u, ~0u})
          ASSERT_EQ(fast.value(n, table.data()), scrambledRadicalInverse(n, base, key));
      }
    }
}

TEST(HaltonSampler, ValuesAreTheReferencesInAnyOrder) {
  // Coordinate c of sample i in pixel p is scrambledRadicalInverse(i, kPrimes[c], key(p, c)),
  // whether a pixel's samples come in order, interleaved with another pixel's, or past the
  // sample count.
  HaltonSampler sampler(16, 9);
  const Point2i pixels[] = {Point2i(3, 4), Point2i(-2, 7)};
  for (int pass = 0; pass < 2; ++pass)
    for (int s = 0; s < 20; ++s)
      for (int k = 0; k < 2; ++k) {
        int i = pass == 0 ? s : 19 - s;
        Point2i p = pixels[k];
        sampler.startPixelSample(p, i);
        Point2f image = sampler.getPixel2D();
        std::vector<Float> values = {image.x, image.y};
        for (int d = 0; d < 30; ++d) values.push_back(sampler.get1D());
        for (uint64_t c = 0; c < values.size(); ++c)
          ASSERT_EQ(values[c], scrambledRadicalInverse(uint32_t(i), kPrimes[c],
                                                       HaltonSampler::coordinateKey(p, c, 9)))
              << "pixel " << p.x << "," << p.y << " sample " << i << " coordinate " << c;
      }
}

TEST(HaltonSampler, ImagePlaneOnePerCellOfTwoToTheAThreeToTheB) {
  // The first 2^a 3^b Halton points (bases 2 and 3) put one point in each cell of a 2^a x 3^b
  // grid (the Chinese remainder theorem); digit scrambling permutes the cells, keeping it so.
  HaltonSampler sampler(36, 8);
  for (Point2i pixel : {Point2i(0, 0), Point2i(12, 40)})
    for (int a = 0; a <= 3; ++a)
      for (int b = 0; b <= 2; ++b) {
        int n = ipow(2, a) * ipow(3, b);
        std::vector<Point2f> pts;
        for (int s = 0; s < n; ++s) {
          sampler.startPixelSample(pixel, s);
          pts.push_back(sampler.getPixel2D());
        }
        EXPECT_TRUE(onePerCell(pts, ipow(2, a), ipow(3, b))) << "a " << a << " b " << b;
      }
}

TEST(HaltonSampler, LaterDimensionsUseTheNextPrimes) {
  // Coordinates 2 and 3 (bases 5 and 7): 25 and 49 samples stratify them.
  HaltonSampler sampler(49, 3);
  std::vector<int> c5(25, 0), c7(49, 0);
  for (int s = 0; s < 49; ++s) {
    sampler.startPixelSample({4, 4}, s);
    Float v5 = sampler.get1D(), v7 = sampler.get1D();
    if (s < 25) ++c5[size_t(double(v5) * 25)];
    ++c7[size_t(double(v7) * 49)];
  }
  for (int c : c5) EXPECT_EQ(c, 1);
  for (int c : c7) EXPECT_EQ(c, 1);
}

TEST(HaltonSampler, ValuesInUnitIntervalPastThePrimeTable) {
  HaltonSampler sampler(4, 1);
  sampler.startPixelSample({1, 2}, 3);
  for (int d = 0; d < 700; ++d) {  // 1400 coordinates: beyond the 1024 primes
    Point2f p = sampler.get2D();
    ASSERT_GE(p.x, 0.f);
    ASSERT_LT(p.x, 1.f);
    ASSERT_GE(p.y, 0.f);
    ASSERT_LT(p.y, 1.f);
  }
}

}  // namespace
}  // namespace candela
