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
  double sum = 0;
  for (int y = 0; y < ny_; ++y) {
    Float py = -radius_.y + (Float(y) + 0.5f) * dy;
    if (py < offsets.pMin.y || py >= offsets.pMax.y) continue;
    for (int x = 0; x < nx_; ++x) {
      Float px = -radius_.x + (Float(x) + 0.5f) * dx;
      if (px >= offsets.pMin.x && px < offsets.pMax.x)
        sum += double(table_[size_t(y) * size_t(nx_) + size_t(x)]);
    }
  }
  return Float(sum * double(dx) * double(dy));
}

}  // namespace candela
