// The box filter (lrt draft §7.7.1): equal weight over [-r, r]^2. pbrt-v2's default pixel filter.
#pragma once

#include "filters/filter.h"

namespace candela {

class BoxFilter final : public Filter {
 public:
  explicit BoxFilter(const Vector2f& radius);
  Float evaluate(const Point2f& p) const override;
  // Uniform over the support: the offset is u scaled, the weight f / pdf the support's area.
  FilterSample sample(const Point2f& u) const override;
};

}  // namespace candela
