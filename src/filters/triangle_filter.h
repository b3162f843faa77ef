// The triangle (tent) filter (lrt draft §7.7.2): per axis max(0, r - |x|), falling linearly from
// r at the centre to zero at the radius. Over its support it integrates to r_x^2 r_y^2.
#pragma once

#include "filters/filter.h"

namespace candela {

class TriangleFilter final : public Filter {
 public:
  explicit TriangleFilter(const Vector2f& radius);
  Float evaluate(const Point2f& p) const override;
};

}  // namespace candela
