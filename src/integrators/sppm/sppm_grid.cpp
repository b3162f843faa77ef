#include "integrators/sppm/sppm_grid.h"

#include <algorithm>
#include <cmath>

namespace candela {

VisiblePointGrid::VisiblePointGrid(std::span<const GridPoint> points, size_t maxCells) {
  if (points.empty()) return;
  Bounds3f bounds;
  Float maxRadius = 0;
  bool first = true;
  for (const GridPoint& g : points) {
    Bounds3f b(g.p - Vector3f(g.radius, g.radius, g.radius),
               g.p + Vector3f(g.radius, g.radius, g.radius));
    bounds = first ? b : unionOf(bounds, b);
    first = false;
    maxRadius = std::max(maxRadius, g.radius);
  }
  Vector3f extent = bounds.diagonal();
  // A cell at least the largest sphere's diameter: a sphere then touches at most 8 cells.
  Float cell = std::max(2 * maxRadius, std::max({extent.x, extent.y, extent.z}) * Float(1e-6));
  if (!(cell > 0)) cell = 1;
  for (;;) {
    double cells = 1;
    for (int a = 0; a < 3; ++a) {
      res_[a] = std::max(1, int(std::min(double(extent[a] / cell) + 1, 1e6)));
      cells *= res_[a];
    }
    if (cells <= double(std::max<size_t>(maxCells, 1))) break;
    cell *= Float(1.26);  // about 2x fewer cells per step
  }
  origin_ = bounds.pMin;
  invCell_ = 1 / cell;
  const size_t nCells = size_t(res_[0]) * res_[1] * res_[2];

  // Two passes (count, then fill) over the points in order: a compact, order-fixed layout.
  auto forEachCell = [&](const GridPoint& g, auto&& visit) {
    int lo[3], hi[3];
    cellOf(g.p - Vector3f(g.radius, g.radius, g.radius), lo);
    cellOf(g.p + Vector3f(g.radius, g.radius, g.radius), hi);
    for (int z = lo[2]; z <= hi[2]; ++z)
      for (int y = lo[1]; y <= hi[1]; ++y)
        for (int x = lo[0]; x <= hi[0]; ++x) visit((size_t(z) * res_[1] + y) * res_[0] + x);
  };
  cellStart_.assign(nCells + 1, 0);
  for (const GridPoint& g : points) forEachCell(g, [&](size_t c) { ++cellStart_[c + 1]; });
  for (size_t c = 0; c < nCells; ++c) cellStart_[c + 1] += cellStart_[c];
  items_.resize(cellStart_[nCells]);
  std::vector<uint32_t> fill(cellStart_.begin(), cellStart_.end() - 1);
  for (size_t i = 0; i < points.size(); ++i)
    forEachCell(points[i], [&](size_t c) { items_[fill[c]++] = uint32_t(i); });
}

// Clamped to the grid; false when p lies outside it.
bool VisiblePointGrid::cellOf(const Point3f& p, int c[3]) const {
  bool inside = true;
  for (int a = 0; a < 3; ++a) {
    Float f = (p[a] - origin_[a]) * invCell_;
    int i = f >= 0 ? int(std::min(f, Float(res_[a]))) : -1;
    if (i < 0 || f > Float(res_[a])) inside = false;  // the far face itself belongs to the grid
    c[a] = std::clamp(i, 0, res_[a] - 1);
  }
  return inside;
}

std::span<const uint32_t> VisiblePointGrid::candidates(const Point3f& p) const {
  if (cellStart_.empty()) return {};
  int c[3];
  if (!cellOf(p, c)) return {};
  size_t cell = (size_t(c[2]) * res_[1] + c[1]) * res_[0] + c[0];
  return std::span<const uint32_t>(items_.data() + cellStart_[cell],
                                   items_.data() + cellStart_[cell + 1]);
}

}  // namespace candela
