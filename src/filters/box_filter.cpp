#include "filters/box_filter.h"

namespace candela {

BoxFilter::BoxFilter(const Vector2f& radius) : Filter(radius) { buildSamplingTable(); }

Float BoxFilter::evaluate(const Point2f& p) const {
  return (std::abs(p.x) <= radius().x && std::abs(p.y) <= radius().y) ? Float(1) : Float(0);
}

}  // namespace candela
