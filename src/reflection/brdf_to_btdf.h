// A BTDF made from a BRDF by mirroring wi to the other side of the surface (lrt draft §9.1):
// translucent materials transmit with the shape of a reflection lobe. f, sampleF and pdf all
// mirror wi's z (the draft's Pdf negated all of wo instead, inconsistent with its f).
#pragma once

#include "reflection/bxdf.h"

namespace candela {

class BRDFToBTDF : public BxDF {
 public:
  explicit BRDFToBTDF(const BxDF* brdf) : BxDF(swapSides(brdf->type())), brdf_(brdf) {}
  Spectrum f(const Vector3f& wo, const Vector3f& wi) const override {
    return brdf_->f(wo, otherHemisphere(wi));
  }
  Spectrum sampleF(const Vector3f& wo, Vector3f* wi, const Point2f& u, Float* pdf,
                   BxDFType* sampledType = nullptr) const override;
  Float pdf(const Vector3f& wo, const Vector3f& wi) const override {
    return brdf_->pdf(wo, otherHemisphere(wi));
  }
  Spectrum rho(const Vector3f& wo, std::span<const Point2f> u) const override {
    return brdf_->rho(wo, u);
  }
  Spectrum rho(std::span<const Point2f> u1, std::span<const Point2f> u2) const override {
    return brdf_->rho(u1, u2);
  }
  // Exchanges the reflection and transmission bits.
  static BxDFType swapSides(BxDFType t) { return BxDFType(t ^ (kReflection | kTransmission)); }

 private:
  const BxDF* brdf_;
};

}  // namespace candela
