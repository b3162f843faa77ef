#include "reflection/fresnel_blend.h"

#include "core/sampling.h"

namespace candela {

namespace {
Float pow5(Float x) { return (x * x) * (x * x) * x; }
}  // namespace

Spectrum FresnelBlend::schlickFresnel(Float cosTheta) const {
  return rs_ + (Spectrum(1) - rs_) * pow5(1 - cosTheta);
}

Spectrum FresnelBlend::f(const Vector3f& wo, const Vector3f& wi) const {
  Float cosO = absCosTheta(wo), cosI = absCosTheta(wi);
  Spectrum diffuse = rd_ * (Spectrum(1) - rs_) *
                     (28 / (23 * kPi) * (1 - pow5(1 - cosI / 2)) * (1 - pow5(1 - cosO / 2)));
  Vector3f wh = wi + wo;
  if (wh.lengthSquared() == 0 || std::max(cosO, cosI) == 0) return diffuse;
  wh = normalize(wh);
  Float hDotI = absDot(wi, wh);
  if (hDotI == 0) return diffuse;
  Spectrum specular =
      schlickFresnel(hDotI) * (distribution_->pdfWh(wh) / (4 * hDotI * std::max(cosO, cosI)));
  return diffuse + specular;
}

Spectrum FresnelBlend::sampleF(const Vector3f& wo, Vector3f* wi, const Point2f& u, Float* pdfOut,
                               BxDFType* sampledType) const {
  if (sampledType) *sampledType = type();
  *pdfOut = 0;
  if (wo.z == 0) return Spectrum(0);
  if (u.x < Float(0.5)) {
    Point2f v(std::min(2 * u.x, kOneMinusEpsilon), u.y);
    *wi = sampleCosineHemisphere(v);
    if (wo.z < 0) wi->z = -wi->z;
  } else {
    Point2f v(std::min(2 * (u.x - Float(0.5)), kOneMinusEpsilon), u.y);
    Float unused;
    *wi = distribution_->sampleWi(wo, v, &unused);
    if (!sameHemisphere(wo, *wi)) return Spectrum(0);
  }
  *pdfOut = pdf(wo, *wi);
  return f(wo, *wi);
}

Float FresnelBlend::pdf(const Vector3f& wo, const Vector3f& wi) const {
  if (!sameHemisphere(wo, wi)) return 0;
  return Float(0.5) * (absCosTheta(wi) * kInvPi + distribution_->pdf(wo, wi));
}

}  // namespace candela
