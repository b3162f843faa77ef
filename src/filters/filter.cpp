#include "filters/filter.h"

#include <cassert>
#include <cmath>

namespace candela {

namespace {
// Table cells are 1/32 of a pixel wide (pbrt 4e §8.8.1 uses 32 per unit radius), with at least 64
// per axis so that narrow filters are still resolved, and at most 1024 to bound memory for very
// wide ones.
constexpr Float kCellsPerPixel = 32;
constexpr int kMinCells = 64;
constexpr int kMaxCells = 1024;

int cellsFor(Float radius) {
  Float n = std::ceil(2 * radius * kCellsPerPixel);
  return clamp(int(std::min(n, Float(kMaxCells))), kMinCells, kMaxCells);
}
}  // namespace

void Filter::buildSamplingTable() {
  nx_ = cellsFor(radius_.x);
  ny_ = cellsFor(radius_.y);
  table_.assign(size_t(nx_) * size_t(ny_), 0);
  Float dx = 2 * radius_.x / Float(nx_), dy = 2 * radius_.y / Float(ny_);
  // f at cell centres: the midpoint rule, second order, and never at the support's edge where
  // most filters are exactly zero.
  double sum = 0;
  for (int y = 0; y < ny_; ++y) {
    Float py = -radius_.y + (Float(y) + 0.5f) * dy;
    for (int x = 0; x < nx_; ++x) {
      Float px = -radius_.x + (Float(x) + 0.5f) * dx;
      Float f = evaluate(Point2f(px, py));
      table_[size_t(y) * size_t(nx_) + size_t(x)] = f;
      sum += double(f);
    }
  }
  integral_ = Float(sum * double(dx) * double(dy));
  prefix_.assign(size_t(nx_ + 1) * size_t(ny_ + 1), 0);
  for (int y = 0; y < ny_; ++y)
    for (int x = 0; x < nx_; ++x)
      prefix_[size_t(y + 1) * size_t(nx_ + 1) + size_t(x + 1)] =
          double(table_[size_t(y) * size_t(nx_) + size_t(x)]) +
          prefix_[size_t(y) * size_t(nx_ + 1) + size_t(x + 1)] +
          prefix_[size_t(y + 1) * size_t(nx_ + 1) + size_t(x)] -
          prefix_[size_t(y) * size_t(nx_ + 1) + size_t(x)];
  // Distribution2D samples |f| (it takes absolute values); negative lobes come back through the
  // sign of the weight.
  distribution_ = std::make_unique<Distribution2D>(table_, nx_, ny_);
}

FilterSample Filter::sample(const Point2f& u) const {
  assert(distribution_ && "concrete filters must call buildSamplingTable()");
  Float pdf01 = 0;
  Point2f s = distribution_->sampleContinuous(u, &pdf01);
  Point2f p(-radius_.x + 2 * radius_.x * s.x, -radius_.y + 2 * radius_.y * s.y);
  // The density over [0,1)^2 divided by the support's area is the density over [-r, r]^2. The
  // weight uses the exact f(p), not the table's value, so E[weight] = integral of f (pbrt 4e
  // §8.8.1); for a constant filter both table and f are constant and so is the weight.
  Float pdf = pdf01 / (4 * radius_.x * radius_.y);
  Float f = evaluate(p);
  return FilterSample{p, pdf > 0 ? f / pdf : Float(0)};
}

Float Filter::integral() const { return integral_; }

Float Filter::integralOver(const Bounds2f& offsets) const {
  Float dx = 2 * radius_.x / Float(nx_), dy = 2 * radius_.y / Float(ny_);
  // The cells whose centres -r + (i + 1/2) d lie in [pMin, pMax): i from the first index at or
  // past pMin to the first past pMax.
  auto firstCell = [](Float p, Float r, Float d, int n) {
    Float i = std::ceil((p + r) / d - 0.5f);  // clamped as a float: p may be far off
    return i > 0 ? int(std::min(i, Float(n))) : 0;
  };
  int x0 = firstCell(offsets.pMin.x, radius_.x, dx, nx_),
      x1 = std::max(x0, firstCell(offsets.pMax.x, radius_.x, dx, nx_));
  int y0 = firstCell(offsets.pMin.y, radius_.y, dy, ny_),
      y1 = std::max(y0, firstCell(offsets.pMax.y, radius_.y, dy, ny_));
  auto at = [&](int x, int y) { return prefix_[size_t(y) * size_t(nx_ + 1) + size_t(x)]; };
  double sum = at(x1, y1) - at(x0, y1) - at(x1, y0) + at(x0, y0);
  return Float(sum * double(dx) * double(dy));
}

}  // namespace candela
