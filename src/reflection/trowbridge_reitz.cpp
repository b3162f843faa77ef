#include "reflection/trowbridge_reitz.h"

#include <limits>

namespace candela {

Float roughnessToAlpha(Float roughness) {
  Float x = std::log(std::max(roughness, Float(1e-3)));
  return 1.62142f + x * (0.819955f + x * (0.1734f + x * (0.0171201f + x * 0.000640711f)));
}

TrowbridgeReitzDistribution::TrowbridgeReitzDistribution(Float alphaX, Float alphaY)
    : alphaX_(std::max(kMinAlpha, alphaX)), alphaY_(std::max(kMinAlpha, alphaY)) {}

Float TrowbridgeReitzDistribution::d(const Vector3f& wh) const {
  // For a unit wh, cos^4 theta (1 + tan^2 theta (cos^2 phi / ax^2 + sin^2 phi / ay^2))^2 is
  // (z^2 + x^2 / ax^2 + y^2 / ay^2)^2: no division by cos theta, finite at the horizon.
  Float sx = wh.x / alphaX_, sy = wh.y / alphaY_;
  Float q = wh.z * wh.z + sx * sx + sy * sy;
  if (q == 0) return 0;
  return 1 / (kPi * alphaX_ * alphaY_ * q * q);
}

Float TrowbridgeReitzDistribution::lambda(const Vector3f& w) const {
  Float z2 = w.z * w.z;
  if (z2 == 0) return std::numeric_limits<Float>::infinity();
  Float ax = alphaX_ * w.x, ay = alphaY_ * w.y;
  Float a2t2 = (ax * ax + ay * ay) / z2;  // alpha(phi)^2 tan^2 theta
  // (sqrt(1 + a) - 1) / 2 written without the cancellation near the normal.
  return a2t2 / (2 * (std::sqrt(1 + a2t2) + 1));
}

Vector3f TrowbridgeReitzDistribution::sampleWh(const Vector3f& wo, const Point2f& u) const {
  bool flip = wo.z < 0;
  Vector3f w = flip ? -wo : wo;
  // wo in the configuration where the distribution is the unit hemisphere (alpha = 1).
  Vector3f v = normalize(Vector3f(alphaX_ * w.x, alphaY_ * w.y, w.z));
  Float len2 = v.x * v.x + v.y * v.y;
  Vector3f t1 = len2 > 0 ? Vector3f(-v.y, v.x, 0) / std::sqrt(len2) : Vector3f(1, 0, 0);
  Vector3f t2 = cross(v, t1);
  // A uniform point on the unit disk; its second coordinate is squeezed into the part of the
  // disk that the hemisphere's projection along v covers (half a disk plus half an ellipse).
  Float r = std::sqrt(u.x), phi = 2 * kPi * u.y;
  Float p1 = r * std::cos(phi), p2 = r * std::sin(phi);
  Float s = Float(0.5) * (1 + v.z);
  p2 = (1 - s) * std::sqrt(std::max(Float(0), 1 - p1 * p1)) + s * p2;
  // Lift back onto the hemisphere and unstretch the normal.
  Float p3 = std::sqrt(std::max(Float(0), 1 - p1 * p1 - p2 * p2));
  Vector3f n = t1 * p1 + t2 * p2 + v * p3;
  Vector3f wh = normalize(Vector3f(alphaX_ * n.x, alphaY_ * n.y, std::max(Float(0), n.z)));
  return flip ? -wh : wh;
}

Float TrowbridgeReitzDistribution::pdf(const Vector3f& wo, const Vector3f& wh) const {
  Float cosO = std::abs(wo.z);
  if (cosO == 0) return 0;
  Float woDotWh = dot(wo, wh.z * wo.z < 0 ? -wh : wh);
  if (woDotWh <= 0) return 0;
  return g1(wo) * woDotWh * d(wh) / cosO;
}

}  // namespace candela
