#include "integrators/tile_grid.h"

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "film/film.h"

namespace candela {

TileGrid::TileGrid(const Bounds2i& region, int count) : region_(region) {
  const int w = region.pMax.x - region.pMin.x, h = region.pMax.y - region.pMin.y;
  if (count < 1) throw std::invalid_argument("the tile count must be at least 1");
  if (w < 1 || h < 1) throw std::invalid_argument("the image region has no pixels");
  // Every factorisation columns x rows that fits; the one whose tiles' aspect ratio is closest to
  // 1 (the least perimeter for the area), fewer columns on a tie.
  double best = INFINITY;
  for (int c = 1; c <= count; ++c) {
    if (count % c != 0) continue;
    const int r = count / c;
    if (c > w || r > h) continue;
    const double misfit = std::abs(std::log((double(w) / c) / (double(h) / r)));
    if (misfit < best) best = misfit, columns_ = c, rows_ = r;
  }
  if (std::isinf(best))
    throw std::invalid_argument("the " + std::to_string(w) + "x" + std::to_string(h) +
                                " pixels cannot be cut into " + std::to_string(count) +
                                " tiles (columns x rows = " + std::to_string(count) +
                                " with at least one pixel each)");
}

Bounds2i TileGrid::tile(int index) const {
  if (index < 0 || index >= count())
    throw std::invalid_argument("tile " + std::to_string(index) + " of a grid of " +
                                std::to_string(count()));
  const int64_t w = region_.pMax.x - region_.pMin.x, h = region_.pMax.y - region_.pMin.y;
  const int64_t c = index % columns_, r = index / columns_;
  auto edge = [](int origin, int64_t size, int64_t k, int64_t n) {
    return origin + int(k * size / n);
  };
  return Bounds2i(
      Point2i(edge(region_.pMin.x, w, c, columns_), edge(region_.pMin.y, h, r, rows_)),
      Point2i(edge(region_.pMin.x, w, c + 1, columns_), edge(region_.pMin.y, h, r + 1, rows_)));
}

Bounds2f cropWindowForPixels(const Bounds2i& pixels, const Point2i& fullResolution) {
  auto ndc = [](int edge, int resolution) {
    if (edge <= 0) return Float(0);
    if (edge >= resolution) return Float(1);
    return Float((double(edge) - 0.5) / double(resolution));
  };
  Bounds2f crop(
      Point2f(ndc(pixels.pMin.x, fullResolution.x), ndc(pixels.pMin.y, fullResolution.y)),
      Point2f(ndc(pixels.pMax.x, fullResolution.x), ndc(pixels.pMax.y, fullResolution.y)));
  if (!(Film::pixelBoundsOf(fullResolution, crop) == pixels))
    throw std::logic_error("crop window does not reproduce the tile's pixels");
  return crop;
}

}  // namespace candela
