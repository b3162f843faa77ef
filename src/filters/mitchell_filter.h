// The Mitchell-Netravali filter (lrt draft §7.7.4; Mitchell & Netravali 1988): a separable cubic
// with parameters B and C; B = C = 1/3 is the authors' recommended trade-off between ringing and
// blurring. It has negative lobes, so its sample weights carry a sign.
#pragma once

#include "filters/filter.h"

namespace candela {

class MitchellFilter final : public Filter {
 public:
  MitchellFilter(const Vector2f& radius, Float b, Float c);
  Float evaluate(const Point2f& p) const override;
  Float b() const { return b_; }
  Float c() const { return c_; }

 private:
  // The cubic on its natural support [-2, 2].
  Float mitchell1D(Float x) const;

  Float b_, c_;
};

}  // namespace candela
