#include "filters/triangle_filter.h"

namespace candela {

TriangleFilter::TriangleFilter(const Vector2f& radius) : Filter(radius) { buildSamplingTable(); }

Float TriangleFilter::evaluate(const Point2f& p) const {
  return std::max(Float(0), radius().x - std::abs(p.x)) *
         std::max(Float(0), radius().y - std::abs(p.y));
}

}  // namespace candela
