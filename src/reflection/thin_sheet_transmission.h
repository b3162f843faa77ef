// Refraction through a thin sheet modelled as one rough interface into index eta (Burley 2015
// §5.2, as pbrt-v3's thin "disney" surfaces do) but with air on both sides: the sheet does not
// change the radiance a ray carries, so the interface's radiance scaling (eta_o / eta_i)^2 is
// undone, f = (eta_i / eta_o)^2 f_interface (eta_i on wi's side). The result is reciprocal and
// transmits at most 1 - F. Sampling is the wrapped BxDF's.
#pragma once

#include "reflection/bxdf.h"

namespace candela {

class ThinSheetTransmission : public BxDF {
 public:
  // interface: a transmission BxDF with index 1 on +z and eta on -z.
  ThinSheetTransmission(const BxDF* interface, Float eta)
      : BxDF(interface->type()), interface_(interface), eta2_(eta * eta) {}
  Spectrum f(const Vector3f& wo, const Vector3f& wi) const override {
    return interface_->f(wo, wi) * scale(wo);
  }
  Spectrum sampleF(const Vector3f& wo, Vector3f* wi, const Point2f& u, Float* pdf,
                   BxDFType* sampledType = nullptr) const override {
    return interface_->sampleF(wo, wi, u, pdf, sampledType) * scale(wo);
  }
  Float pdf(const Vector3f& wo, const Vector3f& wi) const override {
    return interface_->pdf(wo, wi);
  }

 private:
  // (eta_i / eta_o)^2 for a transmitted pair: wi is on the side opposite wo.
  Float scale(const Vector3f& wo) const { return wo.z > 0 ? eta2_ : 1 / eta2_; }
  const BxDF* interface_;
  Float eta2_;
};

}  // namespace candela
