#include "reflection/bxdf.h"

#include "core/sampling.h"

namespace candela {

Spectrum BxDF::sampleF(const Vector3f& wo, Vector3f* wi, const Point2f& u, Float* pdfOut,
                       BxDFType* sampledType) const {
  *wi = sampleCosineHemisphere(u);
  if (wo.z < 0) wi->z = -wi->z;
  *pdfOut = pdf(wo, *wi);
  if (sampledType) *sampledType = type_;
  return f(wo, *wi);
}

Float BxDF::pdf(const Vector3f& wo, const Vector3f& wi) const {
  return sameHemisphere(wo, wi) ? absCosTheta(wi) * kInvPi : 0;
}

}  // namespace candela
