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
  // the +z hemisphere, flipped to wo's side. pdfWh and |wo . wh| are the same for either.
  Vector3f h;
  if (!halfVector(wo, wi, &h)) return 0;
  double woDotWh = std::abs(double(wo.x) * h.x + double(wo.y) * h.y + double(wo.z) * h.z);
  return woDotWh == 0 ? 0 : Float(pdfWh(h) / (4 * woDotWh));
}

bool halfVector(const Vector3f& wo, const Vector3f& wi, Vector3f* wh) {
  double hx = double(wo.x) + wi.x, hy = double(wo.y) + wi.y, hz = double(wo.z) + wi.z;
  double len = std::sqrt(hx * hx + hy * hy + hz * hz);
  if (len == 0) return false;
  *wh = Vector3f(Float(hx / len), Float(hy / len), Float(hz / len));
  return true;
}

namespace {

// |cos theta|^e of a unit vector. Near the pole cos theta rounds to 1 in float, in steps of
// 6e-8, which cos^e turns into steps of e 6e-8 (0.6% at e = 1e5, the largest exponent the
// materials make): there it is taken from sin^2 theta = x^2 + y^2, which keeps its precision.
Float powCos(const Vector3f& w, Float e) {
  double s2 = double(w.x) * w.x + double(w.y) * w.y;
  if (s2 < 0.5) return Float(std::exp(0.5 * double(e) * std::log1p(-s2)));
  return std::pow(absCosTheta(w), e);
}

// cos and sin theta with cos theta = u^(1 / (e + 1)) (Blinn's and Ashikhmin and Shirley's
// sampling), sin theta from 1 - u^(2 / (e + 1)) = -expm1(2 ln u / (e + 1)), so that for large e
// the sampled half vectors are not confined to the few cos theta that float has near 1.
void sampleCosPower(Float u, Float e, Float* cosT, Float* sinT) {
  double sin2 = u > 0 ? -std::expm1(2 * std::log(double(u)) / (double(e) + 1)) : 1;
  *sinT = Float(std::sqrt(sin2));
  *cosT = Float(std::sqrt(1 - sin2));
}

}  // namespace

Float BlinnDistribution::d(const Vector3f& wh) const { return (e_ + 2) * kInv2Pi * powCos(wh, e_); }

Vector3f BlinnDistribution::sampleWh(const Point2f& u) const {
  Float cosT, sinT;
  sampleCosPower(u.x, e_, &cosT, &sinT);
  return sphericalDirection(sinT, cosT, 2 * kPi * u.y);
}

Float BlinnDistribution::pdfWh(const Vector3f& wh) const {
  return (e_ + 1) * kInv2Pi * powCos(wh, e_);
}

Float AnisotropicDistribution::exponent(const Vector3f& wh) const {
  Float s2 = wh.x * wh.x + wh.y * wh.y;
  // At the pole cos theta_h = 1 and any exponent gives 1 (the draft divided 0 by 0, §23).
  if (s2 == 0) return 0;
  return (ex_ * wh.x * wh.x + ey_ * wh.y * wh.y) / s2;
}

Float AnisotropicDistribution::d(const Vector3f& wh) const {
  Float norm = std::sqrt((ex_ + 2) * (ey_ + 2)) * kInv2Pi;
  return norm * powCos(wh, exponent(wh));
}

Float AnisotropicDistribution::pdfWh(const Vector3f& wh) const {
  Float norm = std::sqrt((ex_ + 1) * (ey_ + 1)) * kInv2Pi;
  return norm * powCos(wh, exponent(wh));
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
  Float cosT, sinT;
  sampleCosPower(u.y, e, &cosT, &sinT);
  // Mirror the first-quadrant direction into the chosen quadrant.
  Float x = sinT * cosPhi, y = sinT * sinPhi;
  if (quadrant == 1 || quadrant == 2) x = -x;
  if (quadrant >= 2) y = -y;
  return Vector3f(x, y, cosT);
}

}  // namespace candela
