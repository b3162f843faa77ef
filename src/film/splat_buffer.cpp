#include "film/splat_buffer.h"

#include <cmath>

namespace candela {

namespace {
constexpr double kHiScale = 16;            // hi counts units of 2^-4
constexpr double kLoScale = 4294967296.0;  // lo counts units of 2^-36 (2^32 per hi unit)
constexpr double kMaxHi = 9.0e18 / 2;      // |hi| of one splat, well inside int64
}  // namespace

SplatBuffer::SplatBuffer(const Bounds2i& pixelBounds, const Bounds2f& image, const Filter& filter,
                         Float maxLuminance)
    : bounds_(pixelBounds), filter_(filter), maxLuminance_(maxLuminance) {
  const Vector2f r = filter.radius();
  const Float whole = filter.integral();
  filterIntegrals_.assign(size_t(std::max(0, bounds_.area())), whole);
  for (int y = bounds_.pMin.y; y < bounds_.pMax.y; ++y)
    for (int x = bounds_.pMin.x; x < bounds_.pMax.x; ++x) {
      Point2f c(Float(x) + 0.5f, Float(y) + 0.5f);
      Bounds2f inside(Point2f(image.pMin.x - c.x, image.pMin.y - c.y),
                      Point2f(image.pMax.x - c.x, image.pMax.y - c.y));
      if (inside.pMin.x <= -r.x && inside.pMin.y <= -r.y && inside.pMax.x >= r.x &&
          inside.pMax.y >= r.y)
        continue;
      // A filter with negative lobes could leave little or nothing inside; keep ∫f then.
      Float part = filter.integralOver(inside);
      if (part > Float(1e-3) * whole) filterIntegrals_[index(Point2i(x, y))] = part;
    }
  size_t n = size_t(std::max(0, bounds_.area())) * 6;
  words_ = std::make_unique<std::atomic<int64_t>[]>(n);
  for (size_t i = 0; i < n; ++i) words_[i].store(0, std::memory_order_relaxed);
}

void SplatBuffer::add(const Point2f& pRaster, const Spectrum& splat) {
  if (splat.isBlack()) return;
  if (!splat.isFinite()) {
    refused_.fetch_add(1, std::memory_order_relaxed);
    return;
  }
  Spectrum v = splat;
  if (Float y = v.y(); y > maxLuminance_) v *= maxLuminance_ / y;
  // Pixel (x, y) has its centre c at (x + 0.5, y + 0.5); the ones with pRaster - c in [-r, r),
  // half-open so that a splat on the border of a box filter's support counts once, in the pixel
  // [x, x + 1) that holds it, as camera samples do.
  Vector2f r = filter_.radius();
  int x0 = int(std::floor(pRaster.x - 0.5f - r.x)) + 1,
      x1 = int(std::floor(pRaster.x - 0.5f + r.x));
  int y0 = int(std::floor(pRaster.y - 0.5f - r.y)) + 1,
      y1 = int(std::floor(pRaster.y - 0.5f + r.y));
  x0 = std::max(x0, bounds_.pMin.x), y0 = std::max(y0, bounds_.pMin.y);
  x1 = std::min(x1, bounds_.pMax.x - 1), y1 = std::min(y1, bounds_.pMax.y - 1);
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      Float f = filter_.evaluate(Point2f(pRaster.x - (x + 0.5f), pRaster.y - (y + 0.5f)));
      if (f != 0) addToPixel(Point2i(x, y), v * (f / filterIntegrals_[index(Point2i(x, y))]));
    }
}

size_t SplatBuffer::index(const Point2i& pixel) const {
  return size_t(pixel.y - bounds_.pMin.y) * size_t(bounds_.pMax.x - bounds_.pMin.x) +
         size_t(pixel.x - bounds_.pMin.x);
}

void SplatBuffer::addToPixel(const Point2i& pixel, const Spectrum& v) {
  int64_t hi[3], lo[3];
  for (int c = 0; c < 3; ++c) {
    // Exact in double: v is a float, so 16 v, its floor and the fraction all are.
    double x = double(v[c]) * kHiScale;
    double h = std::floor(x);
    if (!(std::abs(h) < kMaxHi)) {
      refused_.fetch_add(1, std::memory_order_relaxed);
      return;
    }
    hi[c] = int64_t(h);
    lo[c] = std::llround((x - h) * kLoScale);
  }
  size_t w = bounds_.pMax.x - bounds_.pMin.x;
  size_t base = (size_t(pixel.y - bounds_.pMin.y) * w + size_t(pixel.x - bounds_.pMin.x)) * 6;
  for (int c = 0; c < 3; ++c) {
    words_[base + 2 * c].fetch_add(hi[c], std::memory_order_relaxed);
    words_[base + 2 * c + 1].fetch_add(lo[c], std::memory_order_relaxed);
  }
}

Spectrum SplatBuffer::sum(const Point2i& pixel) const {
  if (!bounds_.inside(pixel)) return Spectrum(0);
  size_t w = bounds_.pMax.x - bounds_.pMin.x;
  size_t base = (size_t(pixel.y - bounds_.pMin.y) * w + size_t(pixel.x - bounds_.pMin.x)) * 6;
  Spectrum s;
  for (int c = 0; c < 3; ++c) {
    // hi / 16 + lo / 2^36; lo may exceed 2^32 (carries are not propagated), so it is carried here.
    int64_t hi = words_[base + 2 * c].load(std::memory_order_relaxed);
    int64_t lo = words_[base + 2 * c + 1].load(std::memory_order_relaxed);
    hi += lo >> 32;
    lo &= 0xffffffffLL;
    s[c] = Float((double(hi) + double(lo) / kLoScale) / kHiScale);
  }
  return s;
}

}  // namespace candela
