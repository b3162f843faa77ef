// Splitting an image into pieces for a render farm (`candela --tile I/N`): a grid of N tiles over
// the pixels the film renders. Tile edges lie on pixel boundaries; since every camera sample adds
// only to its own pixel (filter importance sampling, pbrt 4e §8.8), an edge may cut through the
// filter's support and each tile still holds exactly the single render's pixels.
#pragma once

#include "core/bounds.h"

namespace candela {

class TileGrid {
 public:
  // The grid of count tiles (columns x rows = count) over region whose tiles are closest to
  // square; every tile is at least one pixel. Throws std::invalid_argument when count < 1 or no
  // such grid fits in the region (a prime count larger than both of its sides).
  TileGrid(const Bounds2i& region, int count);
  int columns() const { return columns_; }
  int rows() const { return rows_; }
  int count() const { return columns_ * rows_; }
  const Bounds2i& region() const { return region_; }
  // The pixels of tile index (0 <= index < count), row by row from the top left: column k spans
  // [x0 + floor(k W / columns), x0 + floor((k + 1) W / columns)), rows likewise.
  Bounds2i tile(int index) const;

 private:
  Bounds2i region_;
  int columns_ = 1, rows_ = 1;
};

// A crop window (NDC) whose pixel bounds (Film::pixelBoundsOf, ceil at both ends) are exactly
// pixels: each inner edge is put half a pixel before its pixel boundary, so float rounding cannot
// move it across one.
Bounds2f cropWindowForPixels(const Bounds2i& pixels, const Point2i& fullResolution);

}  // namespace candela
