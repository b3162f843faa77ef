#include "filters/mitchell_filter.h"

namespace candela {

MitchellFilter::MitchellFilter(const Vector2f& radius, Float b, Float c)
    : Filter(radius), b_(b), c_(c) {
  buildSamplingTable();
}

Float MitchellFilter::mitchell1D(Float x) const {
  x = std::abs(x);
  Float x2 = x * x, x3 = x2 * x;
  // The two cubic pieces of Mitchell & Netravali's eq. 8, for |x| in [1, 2) and [0, 1).
  if (x >= 2) return 0;
  if (x >= 1)
    return ((-b_ - 6 * c_) * x3 + (6 * b_ + 30 * c_) * x2 + (-12 * b_ - 48 * c_) * x +
            (8 * b_ + 24 * c_)) *
           (Float(1) / 6);
  return ((12 - 9 * b_ - 6 * c_) * x3 + (-18 + 12 * b_ + 6 * c_) * x2 + (6 - 2 * b_)) *
         (Float(1) / 6);
}

Float MitchellFilter::evaluate(const Point2f& p) const {
  // The filter's radius is stretched over the cubic's support [-2, 2] (lrt draft §7.7.4).
  return mitchell1D(2 * p.x / radius().x) * mitchell1D(2 * p.y / radius().y);
}

}  // namespace candela
