// Oren-Nayar rough diffuse reflection (lrt draft §9.4.1): a Lambertian microfacet surface whose
// facet slope angles have standard deviation sigma (degrees). The draft's constructor converted a
// self-initialised copy of sigma (lrt draft §24); here the argument is converted.
#pragma once

#include "reflection/bxdf.h"

namespace candela {

class OrenNayar : public BxDF {
 public:
  OrenNayar(const Spectrum& r, Float sigmaDeg);
  Spectrum f(const Vector3f& wo, const Vector3f& wi) const override;
  Float a() const { return a_; }
  Float b() const { return b_; }

 private:
  Spectrum r_;
  Float a_, b_;
};

}  // namespace candela
