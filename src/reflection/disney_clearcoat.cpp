#include "reflection/disney_clearcoat.h"

#include "reflection/fresnel_blend.h"

namespace candela {

DisneyClearcoat::DisneyClearcoat(Float weight, Float gloss)
    : BxDF(BxDFType(kReflection | kGlossy)),
      weight_(weight),
      distribution_(glossToAlpha(clamp(gloss, 0, 1))),
      masking_(0.25f, 0.25f) {}

Spectrum DisneyClearcoat::f(const Vector3f& wo, const Vector3f& wi) const {
  Float cosO = absCosTheta(wo), cosI = absCosTheta(wi);
  if (cosO == 0 || cosI == 0) return Spectrum(0);
  Vector3f wh = wo + wi;
  if (wh.lengthSquared() == 0) return Spectrum(0);
  wh = normalize(wh);
  // The mean of the two equal cosines keeps f exactly reciprocal in floating point.
  Float cosD = clamp(Float(0.5) * std::abs(dot(wi, wh) + dot(wo, wh)), 0, 1);
  Float fr = schlickFresnel(Spectrum(0.04f), cosD)[0];
  Float g = masking_.g1(wo) * masking_.g1(wi);
  return Spectrum(weight_ / 4 * distribution_.d(wh) * fr * g / (4 * cosO * cosI));
}

Spectrum DisneyClearcoat::sampleF(const Vector3f& wo, Vector3f* wi, const Point2f& u, Float* pdf,
                                  BxDFType* sampledType) const {
  if (sampledType) *sampledType = type();
  *pdf = 0;
  if (wo.z == 0) return Spectrum(0);
  Float unused;
  *wi = distribution_.sampleWi(wo, u, &unused);
  if (!sameHemisphere(wo, *wi)) return Spectrum(0);
  // pdf() from wo and wi again, so that MIS sees exactly the density pdf() reports.
  *pdf = this->pdf(wo, *wi);
  return *pdf == 0 ? Spectrum(0) : f(wo, *wi);
}

Float DisneyClearcoat::pdf(const Vector3f& wo, const Vector3f& wi) const {
  return sameHemisphere(wo, wi) ? distribution_.pdf(wo, wi) : 0;
}

}  // namespace candela
