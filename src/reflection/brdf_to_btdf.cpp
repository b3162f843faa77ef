#include "reflection/brdf_to_btdf.h"

namespace candela {

Spectrum BRDFToBTDF::sampleF(const Vector3f& wo, Vector3f* wi, const Point2f& u, Float* pdf,
                             BxDFType* sampledType) const {
  BxDFType t;
  Spectrum f = brdf_->sampleF(wo, wi, u, pdf, &t);
  *wi = otherHemisphere(*wi);
  if (sampledType) *sampledType = swapSides(t);
  return f;
}

}  // namespace candela
