// The Lanczos-windowed sinc filter (lrt draft §7.7.5; pbrt-v2 LanczosSincFilter). With x
// normalized by the radius (x' = |x| / r), per axis
//   f(x') = sinc(tau x') * sinc(x'),  sinc(t) = sin(pi t) / (pi t),
// for x' <= 1 and 0 beyond: tau lobes of the ideal low-pass sinc under one lobe of the Lanczos
// window. f(0) = 1; below x' = 1e-5 the value is taken as 1 rather than 0/0. The negative lobes
// come back as negative sample weights (see filter.h).
#pragma once

#include "filters/filter.h"

namespace candela {

class LanczosSincFilter final : public Filter {
 public:
  LanczosSincFilter(const Vector2f& radius, Float tau);
  Float evaluate(const Point2f& p) const override;
  Float tau() const { return tau_; }
  // The 1D profile on the normalized axis, x' = x / r.
  Float windowedSinc(Float xNormalized) const;

 private:
  Float tau_;
};

}  // namespace candela
