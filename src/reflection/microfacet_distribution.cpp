#include "reflection/microfacet_distribution.h"

namespace candela {

Vector3f MicrofacetDistribution::sampleWi(const Vector3f& wo, const Point2f& u, Float* pdf) const {
  Vector3f wh = sampleWh(u);
  if (wo.z < 0) wh = -wh;
  Float woDotWh = dot(wo, wh);
  Vector3f wi = -wo + 2 * woDotWh * wh;
  *pdf = woDotWh == 0 ? 0 : pdfWh(wh) / (4 * std::abs(woDotWh));
  return wi;
}

Float MicrofacetDistribution::pdf(const Vector3f& wo, const Vector3f& wi) const {
  // Reflection maps +wh and -wh to the same wi, and exactly one of them was sampled: the one in
  // the +z hemisphere, flipped to wo's side. pdfWh and |wo . wh| are the same for either. The
  // half vector is normalised in double: cos^e theta_h with e in the thousands turns a float
  // normalisation's bias of a fraction of an ulp into a relative error of 1e-4 in the pdf.
  double hx = double(wo.x) + wi.x, hy = double(wo.y) + wi.y, hz = double(wo.z) + wi.z;
  double len = std::sqrt(hx * hx + hy * hy + hz * hz);
  if (len == 0) return 0;
  Vector3f h(Float(hx / len), Float(hy / len), Float(hz / len));
  double woDotWh = std::abs(wo.x * hx + wo.y * hy + wo.z * hz) / len;
  return woDotWh == 0 ? 0 : Float(pdfWh(h) / (4 * woDotWh));
}

Float BlinnDistribution::d(const Vector3f& wh) const {
  return (e_ + 2) * kInv2Pi * std::pow(absCosTheta(wh), e_);
}

Vector3f BlinnDistribution::sampleWh(const Point2f& u) const {
  Float cosT = std::pow(u.x, 1 / (e_ + 1));
  Float sinT = safeSqrt(1 - cosT * cosT);
  return sphericalDirection(sinT, cosT, 2 * kPi * u.y);
}

Float BlinnDistribution::pdfWh(const Vector3f& wh) const {
  return (e_ + 1) * kInv2Pi * std::pow(absCosTheta(wh), e_);
}

Float AnisotropicDistribution::exponent(const Vector3f& wh) const {
  Float s2 = wh.x * wh.x + wh.y * wh.y;
  // At the pole cos theta_h = 1 and any exponent gives 1 (the draft divided 0 by 0, §23).
  if (s2 == 0) return 0;
  return (ex_ * wh.x * wh.x + ey_ * wh.y * wh.y) / s2;
}

Float AnisotropicDistribution::d(const Vector3f& wh) const {
  Float norm = std::sqrt((ex_ + 2) * (ey_ + 2)) * kInv2Pi;
  return norm * std::pow(absCosTheta(wh), exponent(wh));
}

Float AnisotropicDistribution::pdfWh(const Vector3f& wh) const {
  Float norm = std::sqrt((ex_ + 1) * (ey_ + 1)) * kInv2Pi;
  return norm * std::pow(absCosTheta(wh), exponent(wh));
}

Vector3f AnisotropicDistribution::sampleWh(const Point2f& u) const {
  // The density is symmetric about both axes: pick a quadrant with u.x, invert the marginal in
  // phi within the first quadrant, tan phi = sqrt((ex + 1) / (ey + 1)) tan(pi v / 2), then
  // cos theta_h = u.y^(1 / (e(phi) + 1)) (lrt draft §15.3.2, Ashikhmin and Shirley 2000).
  Float scaled = u.x * 4;
  int quadrant = std::min(3, int(scaled));
  Float v = scaled - Float(quadrant);
  Float phi = std::atan(std::sqrt((ex_ + 1) / (ey_ + 1)) * std::tan(kPiOver2 * v));
  Float cosPhi = std::cos(phi), sinPhi = std::sin(phi);
  Float e = ex_ * cosPhi * cosPhi + ey_ * sinPhi * sinPhi;
  Float cosT = std::pow(u.y, 1 / (e + 1));
  Float sinT = safeSqrt(1 - cosT * cosT);
  // Mirror the first-quadrant direction into the chosen quadrant.
  Float x = sinT * cosPhi, y = sinT * sinPhi;
  if (quadrant == 1 || quadrant == 2) x = -x;
  if (quadrant >= 2) y = -y;
  return Vector3f(x, y, cosT);
}

}  // namespace candela
