#include "reflection/fresnel_blend.h"

#include "core/sampling.h"

namespace candela {

namespace {
Float pow5(Float x) { return (x * x) * (x * x) * x; }
}  // namespace

Spectrum schlickFresnel(const Spectrum& rs, Float cosTheta) {
  return rs + (Spectrum(1) - rs) * pow5(1 - cosTheta);
}

Spectrum fresnelBlendDiffuse(const Spectrum& rd, const Spectrum& rs, Float cosO, Float cosI) {
  return rd * (Spectrum(1) - rs) *
         (28 / (23 * kPi) * (1 - pow5(1 - cosI / 2)) * (1 - pow5(1 - cosO / 2)));
}

Spectrum FresnelBlend::schlickFresnel(Float cosTheta) const {
  return candela::schlickFresnel(rs_, cosTheta);
}

Spectrum FresnelBlend::f(const Vector3f& wo, const Vector3f& wi) const {
  Float cosO = absCosTheta(wo), cosI = absCosTheta(wi);
  Spectrum diffuse = fresnelBlendDiffuse(rd_, rs_, cosO, cosI);
  Vector3f wh;
  if (std::max(cosO, cosI) == 0 || !halfVector(wo, wi, &wh)) return diffuse;
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

Spectrum TrowbridgeReitzFresnelBlend::f(const Vector3f& wo, const Vector3f& wi) const {
  Float cosO = absCosTheta(wo), cosI = absCosTheta(wi);
  Spectrum diffuse = fresnelBlendDiffuse(rd_, rs_, cosO, cosI);
  Vector3f wh;
  if (std::max(cosO, cosI) == 0 || !halfVector(wo, wi, &wh)) return diffuse;
  Float hDotI = absDot(wi, wh);
  if (hDotI == 0) return diffuse;
  Spectrum specular =
      schlickFresnel(rs_, hDotI) * (distribution_->d(wh) / (4 * hDotI * std::max(cosO, cosI)));
  return diffuse + specular;
}

Spectrum TrowbridgeReitzFresnelBlend::sampleF(const Vector3f& wo, Vector3f* wi, const Point2f& u,
                                              Float* pdfOut, BxDFType* sampledType) const {
  if (sampledType) *sampledType = type();
  *pdfOut = 0;
  if (wo.z == 0) return Spectrum(0);
  if (u.x < Float(0.5)) {
    Point2f v(std::min(2 * u.x, kOneMinusEpsilon), u.y);
    *wi = sampleCosineHemisphere(v);
    if (wo.z < 0) wi->z = -wi->z;
  } else {
    Point2f v(std::min(2 * (u.x - Float(0.5)), kOneMinusEpsilon), u.y);
    Vector3f wh = distribution_->sampleWh(wo, v);
    Float woDotWh = dot(wo, wh);
    if (woDotWh <= 0) return Spectrum(0);
    *wi = -wo + 2 * woDotWh * wh;
    if (!sameHemisphere(wo, *wi)) return Spectrum(0);
  }
  *pdfOut = pdf(wo, *wi);
  return f(wo, *wi);
}

Float TrowbridgeReitzFresnelBlend::pdf(const Vector3f& wo, const Vector3f& wi) const {
  if (!sameHemisphere(wo, wi)) return 0;
  Vector3f wh = wo + wi;
  Float glossy = 0;
  if (wh.lengthSquared() > 0) {
    wh = normalize(wh);
    Float woDotWh = absDot(wo, wh);
    if (woDotWh > 0) glossy = distribution_->pdf(wo, wh) / (4 * woDotWh);
  }
  return Float(0.5) * (absCosTheta(wi) * kInvPi + glossy);
}

}  // namespace candela
