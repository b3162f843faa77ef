#include "filters/box_filter.h"

namespace candela {

BoxFilter::BoxFilter(const Vector2f& radius) : Filter(radius) { buildSamplingTable(); }

Float BoxFilter::evaluate(const Point2f& p) const {
  return (std::abs(p.x) <= radius().x && std::abs(p.y) <= radius().y) ? Float(1) : Float(0);
}

FilterSample BoxFilter::sample(const Point2f& u) const {
  const Vector2f& r = radius();
  return FilterSample{Point2f(-r.x + 2 * r.x * u.x, -r.y + 2 * r.y * u.y), 4 * r.x * r.y};
}

}  // namespace candela
