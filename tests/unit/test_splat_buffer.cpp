// The splat buffer: sums are the same bits in any order and from any number of threads, within
// the stated 2^-37 per splat of the exact sum over a wide dynamic range; a splat reaches the
// pixels its filter covers with weight f / ∫f; splats outside the bounds are dropped; the film
// adds the splats scaled by its pixel count over the light paths.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <thread>
#include <vector>

#include "film/film.h"
#include "film/splat_buffer.h"
#include "filters/box_filter.h"
#include "filters/gaussian_filter.h"
#include "filters/triangle_filter.h"

namespace candela {
namespace {

struct Splat {
  Point2f p;
  Spectrum v;
};

// Values from 1e-9 to 1e6, both signs in the blue channel (negative filter lobes).
std::vector<Splat> randomSplats(int n, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0, 1);
  std::vector<Splat> s;
  for (int i = 0; i < n; ++i) {
    float mag = std::pow(10.f, -9 + 15 * u(rng));
    s.push_back({Point2f(4 * u(rng), 4 * u(rng)),
                 Spectrum(mag, mag * u(rng), (u(rng) < 0.3f ? -1 : 1) * mag * 0.5f)});
  }
  return s;
}

TEST(SplatBuffer, SameBitsInAnyOrderAndFromTwoThreads) {
  BoxFilter box(Vector2f(0.5f, 0.5f));
  std::vector<Splat> splats = randomSplats(20000, 1);
  Bounds2i bounds(Point2i(0, 0), Point2i(4, 4));
  Bounds2f image(Point2f(0, 0), Point2f(4, 4));
  SplatBuffer forward(bounds, image, box), backward(bounds, image, box),
      threaded(bounds, image, box);
  for (const Splat& s : splats) forward.add(s.p, s.v);
  for (auto it = splats.rbegin(); it != splats.rend(); ++it) backward.add(it->p, it->v);
  std::thread a([&] {
    for (size_t i = 0; i < splats.size(); i += 2) threaded.add(splats[i].p, splats[i].v);
  });
  std::thread b([&] {
    for (size_t i = 1; i < splats.size(); i += 2) threaded.add(splats[i].p, splats[i].v);
  });
  a.join();
  b.join();
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x)
      for (int c = 0; c < 3; ++c) {
        Float f = forward.sum(Point2i(x, y))[c];
        EXPECT_EQ(f, backward.sum(Point2i(x, y))[c]);
        EXPECT_EQ(f, threaded.sum(Point2i(x, y))[c]);
      }
  EXPECT_EQ(forward.refused(), 0u);
}

TEST(SplatBuffer, WithinTheQuantumOfTheExactSum) {
  BoxFilter box(Vector2f(0.5f, 0.5f));
  std::vector<Splat> splats = randomSplats(5000, 2);
  Bounds2i bounds(Point2i(0, 0), Point2i(4, 4));
  SplatBuffer buf(bounds, Bounds2f(Point2f(0, 0), Point2f(4, 4)), box);
  long double exact[4][4][3] = {};
  int count[4][4] = {};
  for (const Splat& s : splats) {
    buf.add(s.p, s.v);
    int x = int(s.p.x), y = int(s.p.y);
    ++count[y][x];
    for (int c = 0; c < 3; ++c) exact[y][x][c] += s.v[c];
  }
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x)
      for (int c = 0; c < 3; ++c) {
        double e = double(exact[y][x][c]);
        // Fixed-point rounding plus the final conversion to float.
        double bound = count[y][x] * std::ldexp(1.0, -37) + std::abs(e) * 0x1p-24;
        EXPECT_NEAR(buf.sum(Point2i(x, y))[c], e, bound) << x << " " << y << " " << c;
      }
}

// A triangle filter of radius 1 covers the four pixels around a point with weights
// (1 - |dx|)(1 - |dy|), which sum to 1 (its integral is 1).
TEST(SplatBuffer, FilterWeightsAndBounds) {
  TriangleFilter tri(Vector2f(1, 1));
  Bounds2i bounds(Point2i(1, 1), Point2i(5, 5));
  SplatBuffer buf(bounds, Bounds2f(Point2f(0, 0), Point2f(6, 6)), tri);
  buf.add(Point2f(2.75f, 3.25f), Spectrum(1));  // centres (2.5, 2.5)...(3.5, 3.5)
  Float fi = tri.integral();
  EXPECT_NEAR(fi, 1, 1e-3f);
  EXPECT_NEAR(buf.sum(Point2i(2, 2))[0], 0.75f * 0.25f / fi, 1e-6f);
  EXPECT_NEAR(buf.sum(Point2i(3, 2))[0], 0.25f * 0.25f / fi, 1e-6f);
  EXPECT_NEAR(buf.sum(Point2i(2, 3))[0], 0.75f * 0.75f / fi, 1e-6f);
  EXPECT_NEAR(buf.sum(Point2i(3, 3))[0], 0.25f * 0.75f / fi, 1e-6f);
  EXPECT_EQ(buf.sum(Point2i(1, 1))[0], 0);
  // Outside the bounds: dropped, and the pixels inside get only their own share.
  buf.add(Point2f(0.6f, 0.6f), Spectrum(5));
  EXPECT_NEAR(buf.sum(Point2i(1, 1))[0], 5 * 0.1f * 0.1f / fi, 1e-5f);
  EXPECT_EQ(buf.sum(Point2i(0, 0))[0], 0);
}

TEST(SplatBuffer, FilmAddsSplatsScaledByPixelsOverLightPaths) {
  Film film(Point2i(4, 2), Bounds2f(Point2f(0, 0), Point2f(1, 1)),
            std::make_unique<BoxFilter>(Vector2f(0.5f, 0.5f)), "x.exr");
  film.addSample(Point2i(1, 1), Spectrum(2), 1, 1);
  film.enableSplats().add(Point2f(1.5f, 1.5f), Spectrum(3));
  film.addLightPaths(16);  // 2 per pixel
  EXPECT_FLOAT_EQ(film.pixelValue(Point2i(1, 1))[0], 2 + 3 * 8.f / 16);
  EXPECT_FLOAT_EQ(film.pixelValue(Point2i(0, 0))[0], 0);
}

// A box filter's support borders: a splat on a pixel border counts once, in the pixel that holds
// it ([x, x + 1)).
TEST(SplatBuffer, BoxBorderCountsOnce) {
  BoxFilter box(Vector2f(0.5f, 0.5f));
  SplatBuffer buf(Bounds2i(Point2i(0, 0), Point2i(3, 3)), Bounds2f(Point2f(0, 0), Point2f(3, 3)),
                  box);
  buf.add(Point2f(1, 2), Spectrum(1));
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 3; ++x)
      EXPECT_EQ(buf.sum(Point2i(x, y))[0], (x == 1 && y == 2) ? 1.f : 0.f) << x << " " << y;
}

// Splats come only from inside the image, so near its edges part of a wide filter's support gets
// none. A constant splatted densely over the image must still come out constant on every pixel,
// the corners included (weighted by the part of ∫f inside the image, not all of it: with ∫f the
// corner pixel of this Gaussian came out 0.70 and an edge pixel 0.84), in a crop too.
TEST(SplatBuffer, ConstantSplatsStayConstantUpToTheImageEdges) {
  GaussianFilter gaussian(Vector2f(2, 2), 2);
  const Bounds2f image(Point2f(0, 0), Point2f(6, 5));
  SplatBuffer whole(Bounds2i(Point2i(0, 0), Point2i(6, 5)), image, gaussian);
  SplatBuffer crop(Bounds2i(Point2i(4, 0), Point2i(6, 2)), image, gaussian);
  // A 64 x 64 grid of splats a pixel, each carrying its share of unit density.
  constexpr int n = 64;
  const Spectrum share(1.f / (n * n));
  for (int y = 0; y < 5 * n; ++y)
    for (int x = 0; x < 6 * n; ++x) {
      Point2f p((Float(x) + 0.5f) / n, (Float(y) + 0.5f) / n);
      whole.add(p, share);
      crop.add(p, share);
    }
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 6; ++x) {
      // The grid's sum against the filter table's quadrature: both second order in 1/64 and 1/32.
      EXPECT_NEAR(whole.sum(Point2i(x, y))[0], 1, 2e-3f) << x << " " << y;
      if (x >= 4 && y < 2) {
        EXPECT_EQ(crop.sum(Point2i(x, y))[0], whole.sum(Point2i(x, y))[0]);
      }
    }
}

TEST(SplatBuffer, RefusesNonFinite) {
  BoxFilter box(Vector2f(0.5f, 0.5f));
  SplatBuffer buf(Bounds2i(Point2i(0, 0), Point2i(1, 1)), Bounds2f(Point2f(0, 0), Point2f(1, 1)),
                  box);
  buf.add(Point2f(0.5f, 0.5f), Spectrum(std::numeric_limits<Float>::infinity()));
  EXPECT_EQ(buf.refused(), 1u);
  EXPECT_EQ(buf.sum(Point2i(0, 0))[0], 0);
}

}  // namespace
}  // namespace candela
