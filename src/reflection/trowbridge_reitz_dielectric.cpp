#include "reflection/trowbridge_reitz_dielectric.h"

#include "core/rng.h"

namespace candela {

Float TrowbridgeReitzDielectric::reflectProbability(const Vector3f& wo, const Vector3f& wh) const {
  // The cosine's sign says which side the light meets the microfacet from (fresnelDielectric's
  // convention), as TrowbridgeReitzReflection::f evaluates it.
  Float cosO = dot(wo, wh);
  Float fr =
      fresnelDielectric(wo.z > 0 ? cosO : -cosO, fresnel_.etaOutside(), fresnel_.etaInside());
  Float pr = fr * rMean_, pt = (1 - fr) * tMean_;
  return pr + pt > 0 ? pr / (pr + pt) : -1;
}

Spectrum TrowbridgeReitzDielectric::f(const Vector3f& wo, const Vector3f& wi) const {
  return sameHemisphere(wo, wi) ? reflection_.f(wo, wi) : transmission_.f(wo, wi);
}

Float TrowbridgeReitzDielectric::pdf(const Vector3f& wo, const Vector3f& wi) const {
  if (wo.z == 0 || wi.z == 0) return 0;
  Vector3f wh;
  if (sameHemisphere(wo, wi)) {
    wh = wo + wi;
    if (wh.lengthSquared() == 0) return 0;
    wh = normalize(wh);
    if (wh.z * wo.z < 0) wh = -wh;
    Float pr = reflectProbability(wo, wh);
    return pr > 0 ? pr * reflection_.pdf(wo, wi) : 0;
  }
  if (!transmission_.halfVector(wo, wi, &wh)) return 0;
  Float pr = reflectProbability(wo, wh);
  return pr >= 0 && pr < 1 ? (1 - pr) * transmission_.pdf(wo, wi) : 0;
}

Spectrum TrowbridgeReitzDielectric::sampleChoosing(const Vector3f& wo, Vector3f* wi, Float uChoice,
                                                   const Point2f& u, Float* pdf,
                                                   BxDFType* sampledType) const {
  *pdf = 0;
  if (sampledType) *sampledType = type();
  if (wo.z == 0) return Spectrum(0);
  Vector3f wh = distribution_->sampleWh(wo, u);
  Float cosO = dot(wo, wh);
  if (cosO <= 0) return Spectrum(0);
  Float pr = reflectProbability(wo, wh);
  if (pr < 0) return Spectrum(0);
  if (uChoice < pr) {
    if (sampledType) *sampledType = BxDFType(kReflection | kGlossy);
    *wi = -wo + 2 * cosO * wh;
    if (!sameHemisphere(wo, *wi)) return Spectrum(0);
  } else {
    if (sampledType) *sampledType = BxDFType(kTransmission | kGlossy);
    // Snell's law at the microfacet, e = eta_o / eta_i (pr < 1: it refracts).
    bool outside = wo.z > 0;
    Float e = outside ? fresnel_.etaOutside() / fresnel_.etaInside()
                      : fresnel_.etaInside() / fresnel_.etaOutside();
    Float sin2T = e * e * std::max(Float(0), 1 - cosO * cosO);
    if (sin2T >= 1) return Spectrum(0);
    Float cosT = std::sqrt(1 - sin2T);
    *wi = normalize(-e * wo + (e * cosO - cosT) * wh);
    if (sameHemisphere(wo, *wi)) return Spectrum(0);
  }
  // Density and value from wo and wi again, so that MIS sees exactly what pdf() reports.
  *pdf = this->pdf(wo, *wi);
  return *pdf == 0 ? Spectrum(0) : f(wo, *wi);
}

Spectrum TrowbridgeReitzDielectric::sampleF(const Vector3f& wo, Vector3f* wi, const Point2f& u,
                                            Float* pdf, BxDFType* sampledType) const {
  uint64_t bits = (uint64_t(floatToBits(u.x)) << 32) | floatToBits(u.y);
  Float uChoice = Float(mixBits(bits) >> 40) * 0x1p-24f;
  return sampleChoosing(wo, wi, uChoice, u, pdf, sampledType);
}

}  // namespace candela
