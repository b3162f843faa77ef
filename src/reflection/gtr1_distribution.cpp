#include "reflection/gtr1_distribution.h"

namespace candela {

Gtr1Distribution::Gtr1Distribution(Float alpha) : alpha_(clamp(alpha, 1e-4f, 0.9999f)) {}

Float Gtr1Distribution::d(const Vector3f& wh) const {
  Float a2 = alpha_ * alpha_, c = cosTheta(wh);
  return (a2 - 1) / (kPi * std::log(a2) * (1 + (a2 - 1) * c * c));
}

Vector3f Gtr1Distribution::sampleWh(const Point2f& u) const {
  Float a2 = alpha_ * alpha_;
  Float cos2 = (1 - std::pow(a2, 1 - u.x)) / (1 - a2);
  Float cosT = std::sqrt(clamp(cos2, 0, 1));
  return sphericalDirection(safeSqrt(1 - cosT * cosT), cosT, 2 * kPi * u.y);
}

}  // namespace candela
