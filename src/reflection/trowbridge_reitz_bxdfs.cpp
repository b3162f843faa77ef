#include "reflection/trowbridge_reitz_bxdfs.h"

namespace candela {

namespace {
// Mirror reflection of wo about the microfacet normal wh.
Vector3f reflectAbout(const Vector3f& wo, const Vector3f& wh) { return -wo + 2 * dot(wo, wh) * wh; }
}  // namespace

Spectrum TrowbridgeReitzReflection::f(const Vector3f& wo, const Vector3f& wi) const {
  Float cosO = absCosTheta(wo), cosI = absCosTheta(wi);
  if (cosO == 0 || cosI == 0) return Spectrum(0);
  Vector3f wh = wi + wo;
  if (wh.lengthSquared() == 0) return Spectrum(0);
  wh = normalize(wh);
  // As in pbrt-v2's model (reflection/microfacet.h): the cosine against the half vector turned to
  // +z, negative from inside a dielectric, where total internal reflection then applies. wi and
  // wo make the same angle with wh; their mean keeps f exactly reciprocal in floating point,
  // which matters on the steep slope of the Fresnel term near the critical angle.
  Vector3f up = faceForward(wh, Vector3f(0, 0, 1));
  Spectrum fr = fresnel_->evaluate(Float(0.5) * (dot(wi, up) + dot(wo, up)));
  return r_ * fr * (distribution_->d(wh) * distribution_->g(wo, wi) / (4 * cosI * cosO));
}

Spectrum TrowbridgeReitzReflection::sampleF(const Vector3f& wo, Vector3f* wi, const Point2f& u,
                                            Float* pdf, BxDFType* sampledType) const {
  if (sampledType) *sampledType = type();
  *pdf = 0;
  if (wo.z == 0) return Spectrum(0);
  Vector3f wh = distribution_->sampleWh(wo, u);
  if (dot(wo, wh) <= 0) return Spectrum(0);
  *wi = reflectAbout(wo, wh);
  if (!sameHemisphere(wo, *wi)) return Spectrum(0);
  // pdf() from wo and wi again, so that MIS sees exactly the density pdf() reports.
  *pdf = this->pdf(wo, *wi);
  return *pdf == 0 ? Spectrum(0) : f(wo, *wi);
}

Float TrowbridgeReitzReflection::pdf(const Vector3f& wo, const Vector3f& wi) const {
  if (!sameHemisphere(wo, wi)) return 0;
  Vector3f wh = wo + wi;
  if (wh.lengthSquared() == 0) return 0;
  wh = normalize(wh);
  Float woDotWh = std::abs(dot(wo, wh));
  return woDotWh == 0 ? 0 : distribution_->pdf(wo, wh) / (4 * woDotWh);
}

bool TrowbridgeReitzTransmission::halfVector(const Vector3f& wo, const Vector3f& wi,
                                             Vector3f* wh) const {
  if (wo.z == 0 || wi.z == 0 || sameHemisphere(wo, wi)) return false;
  Vector3f h = wo + wi * etaRatio(wo);
  if (h.lengthSquared() == 0) return false;  // equal indices at normal incidence
  h = normalize(h);
  if (h.z * wo.z < 0) h = -h;
  *wh = h;
  return dot(wo, h) > 0 && dot(wi, h) < 0;
}

Spectrum TrowbridgeReitzTransmission::f(const Vector3f& wo, const Vector3f& wi) const {
  Vector3f wh;
  if (!halfVector(wo, wi, &wh)) return Spectrum(0);
  Float eta = etaRatio(wo);
  Float woDotWh = dot(wo, wh), wiDotWh = dot(wi, wh);
  Float denom = woDotWh + eta * wiDotWh;
  if (denom == 0) return Spectrum(0);
  // The microfacet refracts wo into wi: both cosines are known, and the Fresnel term from both is
  // symmetric in the two directions and well conditioned (from the denser side alone it is not,
  // near the critical angle).
  bool outside = wo.z > 0;
  Float etaO = outside ? fresnel_.etaOutside() : fresnel_.etaInside();
  Float etaI = outside ? fresnel_.etaInside() : fresnel_.etaOutside();
  Float fr = frDielectric(woDotWh, -wiDotWh, etaO, etaI);
  Float value = distribution_->d(wh) * distribution_->g(wo, wi) * std::abs(wiDotWh) * woDotWh /
                (absCosTheta(wo) * absCosTheta(wi) * denom * denom);
  return t_ * ((1 - fr) * value);
}

Spectrum TrowbridgeReitzTransmission::sampleF(const Vector3f& wo, Vector3f* wi, const Point2f& u,
                                              Float* pdf, BxDFType* sampledType) const {
  if (sampledType) *sampledType = type();
  *pdf = 0;
  if (wo.z == 0) return Spectrum(0);
  Vector3f wh = distribution_->sampleWh(wo, u);
  Float cosI = dot(wo, wh);
  if (cosI <= 0) return Spectrum(0);
  // Snell's law at the microfacet, e = eta_o / eta_i; past the critical angle nothing refracts.
  Float e = 1 / etaRatio(wo);
  Float sin2T = e * e * std::max(Float(0), 1 - cosI * cosI);
  if (sin2T >= 1) return Spectrum(0);
  Float cosT = std::sqrt(1 - sin2T);
  *wi = normalize(-e * wo + (e * cosI - cosT) * wh);
  *pdf = this->pdf(wo, *wi);
  return *pdf == 0 ? Spectrum(0) : f(wo, *wi);
}

Float TrowbridgeReitzTransmission::pdf(const Vector3f& wo, const Vector3f& wi) const {
  Vector3f wh;
  if (!halfVector(wo, wi, &wh)) return 0;
  Float eta = etaRatio(wo);
  Float wiDotWh = dot(wi, wh);
  Float denom = dot(wo, wh) + eta * wiDotWh;
  if (denom == 0) return 0;
  return distribution_->pdf(wo, wh) * eta * eta * std::abs(wiDotWh) / (denom * denom);
}

}  // namespace candela
