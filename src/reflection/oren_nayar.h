// Oren-Nayar rough diffuse reflection (lrt draft §9.4). sigma is the standard deviation of the
// microfacet slope angle in degrees; the draft's constructor converted a self-initialised copy,
// here the argument is converted.
#pragma once

#include "reflection/bxdf.h"

namespace candela {

class OrenNayar : public BxDF {
 public:
  OrenNayar(const Spectrum& r, Float sigmaDeg);
  Spectrum f(const Vector3f& wo, const Vector3f& wi) const override;

 private:
  Spectrum r_;
  Float a_, b_;
};

}  // namespace candela
