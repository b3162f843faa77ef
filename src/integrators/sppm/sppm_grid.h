// The uniform grid that finds, for a photon, the SPPM visible points whose search spheres hold it
// (Hachisuka & Jensen 2009 §4; pbrt 3e §16.2.3 hashes the same cells). Each point is listed in
// every cell its sphere overlaps, so a photon looks in one cell only. Rebuilt every iteration, as
// the radii shrink. The lists are built in point order, so the grid is the same for any threads.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/bounds.h"

namespace candela {

struct GridPoint {
  Point3f p;
  Float radius = 0;
};

class VisiblePointGrid {
 public:
  VisiblePointGrid() = default;
  // maxCells bounds the dense cell array; cells grow past 2 * the largest radius to keep within it.
  VisiblePointGrid(std::span<const GridPoint> points, size_t maxCells);
  // The indices of the points listed in the cell holding p (a superset of those whose sphere
  // holds p; the caller tests the distance).
  std::span<const uint32_t> candidates(const Point3f& p) const;
  size_t memoryBytes() const {
    return cellStart_.size() * sizeof(uint32_t) + items_.size() * sizeof(uint32_t);
  }

 private:
  bool cellOf(const Point3f& p, int c[3]) const;
  Point3f origin_;
  Float invCell_ = 0;
  int res_[3] = {0, 0, 0};
  std::vector<uint32_t> cellStart_;  // res_ product + 1 offsets into items_
  std::vector<uint32_t> items_;
};

}  // namespace candela
