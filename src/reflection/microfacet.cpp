#include "reflection/microfacet.h"

namespace candela {

Float vGrooveG(const Vector3f& wo, const Vector3f& wi, const Vector3f& wh) {
  Float nDotH = absCosTheta(wh), woDotH = absDot(wo, wh);
  if (woDotH == 0) return 0;
  Float go = 2 * nDotH * absCosTheta(wo) / woDotH;
  Float gi = 2 * nDotH * absCosTheta(wi) / woDotH;
  return std::min(Float(1), std::min(go, gi));
}

Spectrum MicrofacetReflection::f(const Vector3f& wo, const Vector3f& wi) const {
  Float cosO = absCosTheta(wo), cosI = absCosTheta(wi);
  if (cosO == 0 || cosI == 0) return Spectrum(0);
  Vector3f wh;
  if (!halfVector(wo, wi, &wh)) return Spectrum(0);
  // The cosine is taken against the half vector turned to +z, so that reflection from inside a
  // dielectric (both directions below) sees a negative cosine: the exiting case, with total
  // internal reflection past the critical angle.
  Float cosH = dot(wi, faceForward(wh, Vector3f(0, 0, 1)));
  Spectrum fr = fresnel_->evaluate(cosH);
  return r_ * fr * (distribution_->d(wh) * vGrooveG(wo, wi, wh) / (4 * cosI * cosO));
}

Spectrum MicrofacetReflection::sampleF(const Vector3f& wo, Vector3f* wi, const Point2f& u,
                                       Float* pdf, BxDFType* sampledType) const {
  if (sampledType) *sampledType = type();
  *pdf = 0;
  if (wo.z == 0) return Spectrum(0);
  Float unused;
  *wi = distribution_->sampleWi(wo, u, &unused);
  if (!sameHemisphere(wo, *wi)) return Spectrum(0);
  // pdf() recomputes the half vector from wo and wi; returning exactly that value keeps MIS
  // weights consistent where rounding separates it from the sampled half vector's (grazing wo).
  *pdf = distribution_->pdf(wo, *wi);
  return f(wo, *wi);
}

Float MicrofacetReflection::pdf(const Vector3f& wo, const Vector3f& wi) const {
  return sameHemisphere(wo, wi) ? distribution_->pdf(wo, wi) : 0;
}

}  // namespace candela
