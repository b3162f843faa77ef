// The farm's tile grid: N tiles that partition the image region exactly (every pixel in one tile),
// as square as N's factorisations allow; crop windows that give back exactly a tile's pixels.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "film/film.h"
#include "integrators/tile_grid.h"

namespace candela {
namespace {

// How many tiles of grid hold each pixel of its region.
std::vector<int> coverage(const TileGrid& grid) {
  const Bounds2i r = grid.region();
  const int w = r.pMax.x - r.pMin.x;
  std::vector<int> count(size_t(r.area()), 0);
  for (int t = 0; t < grid.count(); ++t) {
    const Bounds2i b = grid.tile(t);
    EXPECT_FALSE(b.empty()) << "tile " << t;
    for (int y = b.pMin.y; y < b.pMax.y; ++y)
      for (int x = b.pMin.x; x < b.pMax.x; ++x) {
        if (!r.inside(Point2i(x, y))) {
          ADD_FAILURE() << "tile " << t << " leaves the region at " << x << "," << y;
          continue;
        }
        ++count[size_t((y - r.pMin.y) * w + (x - r.pMin.x))];
      }
  }
  return count;
}

TEST(TileGrid, TilesPartitionTheRegion) {
  const Bounds2i regions[] = {
      Bounds2i(Point2i(0, 0), Point2i(256, 256)), Bounds2i(Point2i(0, 0), Point2i(61, 47)),
      Bounds2i(Point2i(13, 7), Point2i(50, 19)), Bounds2i(Point2i(0, 0), Point2i(24, 8)),
      Bounds2i(Point2i(5, 5), Point2i(6, 40))};
  for (const Bounds2i& r : regions)
    for (int n : {1, 2, 3, 4, 5, 7, 8, 12, 16, 35}) {
      const int w = r.pMax.x - r.pMin.x, h = r.pMax.y - r.pMin.y;
      bool fits = false;
      for (int c = 1; c <= n; ++c) fits = fits || (n % c == 0 && c <= w && n / c <= h);
      if (!fits) {
        EXPECT_THROW(TileGrid(r, n), std::invalid_argument) << n << " tiles of " << w << "x" << h;
        continue;
      }
      TileGrid grid(r, n);
      EXPECT_EQ(grid.count(), n);
      for (int c : coverage(grid)) ASSERT_EQ(c, 1) << n << " tiles of " << w << "x" << h;
    }
}

TEST(TileGrid, ChoosesTheSquarestTiles) {
  const Bounds2i square(Point2i(0, 0), Point2i(256, 256));
  EXPECT_EQ(TileGrid(square, 4).columns(), 2);
  EXPECT_EQ(TileGrid(square, 16).columns(), 4);
  EXPECT_EQ(TileGrid(square, 8).columns() * TileGrid(square, 8).rows(), 8);
  // 24 x 8: 8 columns of 2 rows gives 3 x 4 tiles, the nearest to square.
  const TileGrid strip(Bounds2i(Point2i(0, 0), Point2i(24, 8)), 16);
  EXPECT_EQ(strip.columns(), 8);
  EXPECT_EQ(strip.tile(9), Bounds2i(Point2i(3, 4), Point2i(6, 8)));
  // A prime count makes strips across the longer side.
  EXPECT_EQ(TileGrid(Bounds2i(Point2i(0, 0), Point2i(61, 47)), 7).columns(), 7);
}

TEST(TileGrid, RefusesWhatCannotBeTiled) {
  const Bounds2i r(Point2i(0, 0), Point2i(5, 5));
  EXPECT_THROW(TileGrid(r, 0), std::invalid_argument);
  EXPECT_THROW(TileGrid(r, 7), std::invalid_argument);  // 7x1 and 1x7 do not fit in 5x5
  EXPECT_THROW(TileGrid(Bounds2i(), 1), std::invalid_argument);
  EXPECT_THROW(TileGrid(r, 4).tile(4), std::invalid_argument);
}

TEST(TileGrid, CropWindowsGiveBackExactlyTheTilesPixels) {
  // Every edge of small images, and random ones up to the film's largest side (2^20), where
  // float NDC values are coarsest.
  for (int res = 1; res <= 300; ++res)
    for (int a = 0; a <= res; ++a) {
      const int b = std::min(res, a + 1 + a % 7);
      if (a == b) continue;
      const Bounds2i pixels(Point2i(a, 0), Point2i(b, res));
      EXPECT_EQ(
          Film::pixelBoundsOf(Point2i(res, res), cropWindowForPixels(pixels, Point2i(res, res))),
          pixels);
    }
  std::mt19937 rng(5);
  for (int i = 0; i < 20000; ++i) {
    const int res = 1 + int(rng() % (1u << 20));
    int a = int(rng() % unsigned(res)), b = 1 + int(rng() % unsigned(res));
    if (a >= b) std::swap(a, b), ++b;
    if (b > res) continue;
    const Bounds2i pixels(Point2i(a, a), Point2i(b, b));
    ASSERT_EQ(
        Film::pixelBoundsOf(Point2i(res, res), cropWindowForPixels(pixels, Point2i(res, res))),
        pixels)
        << "[" << a << ", " << b << ") of " << res;
  }
}

}  // namespace
}  // namespace candela
