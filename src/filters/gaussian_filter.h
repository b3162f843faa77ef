// The truncated Gaussian filter (lrt draft §7.7.3): per axis e^{-alpha x^2} - e^{-alpha r^2},
// shifted down so that it falls to exactly zero at the radius instead of jumping there.
#pragma once

#include "filters/filter.h"

namespace candela {

class GaussianFilter final : public Filter {
 public:
  GaussianFilter(const Vector2f& radius, Float alpha);
  Float evaluate(const Point2f& p) const override;
  Float alpha() const { return alpha_; }

 private:
  Float gaussian1D(Float x, Float expAtRadius) const;

  Float alpha_;
  Float expX_, expY_;  // e^{-alpha r^2} per axis
};

}  // namespace candela
