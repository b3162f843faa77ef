// The generalised Trowbridge-Reitz distribution with exponent 1 ("GTR1", Berry's distribution),
// the long-tailed lobe of Disney's clearcoat (Burley 2012, §5.4 and Appendix B.2):
//   D(wh) = (alpha^2 - 1) / (pi ln(alpha^2) (1 + (alpha^2 - 1) cos^2 theta_h)),
// normalised over projected area for 0 < alpha < 1. Sampling inverts its cdf in cos^2 theta_h,
// cos^2 theta_h = (1 - alpha^(2 (1 - u))) / (1 - alpha^2), with density D(wh) |cos theta_h|.
#pragma once

#include "reflection/microfacet_distribution.h"

namespace candela {

class Gtr1Distribution final : public MicrofacetDistribution {
 public:
  // alpha is kept inside [1e-4, 0.9999]: at 1 the distribution is uniform in projected area and
  // the formula divides 0 by 0.
  explicit Gtr1Distribution(Float alpha);
  Float d(const Vector3f& wh) const override;
  Vector3f sampleWh(const Point2f& u) const override;
  Float pdfWh(const Vector3f& wh) const override { return d(wh) * absCosTheta(wh); }
  Float alpha() const { return alpha_; }

 private:
  Float alpha_;
};

}  // namespace candela
