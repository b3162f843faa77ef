// The Fresnel term of the Disney specular lobe (Burley 2012, §5.5; Burley 2015, §3.1): the
// exact dielectric reflectance for the index eta blended towards Schlick's approximation with a
// coloured normal-incidence reflectance r0 by the metallic weight,
//   F(c) = (1 - metallic) F_dielectric(c; 1, eta) + metallic (r0 + (1 - r0) (1 - |c|)^5).
// A negative cosine (from inside) gives the dielectric part's total internal reflection, unless
// the surface is two-sided: a thin sheet has air on both sides and reflects alike from either.
#pragma once

#include "reflection/fresnel.h"
#include "reflection/fresnel_blend.h"

namespace candela {

class DisneyFresnel final : public Fresnel {
 public:
  DisneyFresnel(const Spectrum& r0, Float metallic, Float eta, bool twoSided = false)
      : r0_(r0), metallic_(metallic), eta_(eta), twoSided_(twoSided) {}
  Spectrum evaluate(Float cosI) const override {
    Spectrum dielectric(fresnelDielectric(twoSided_ ? std::abs(cosI) : cosI, 1, eta_));
    return dielectric * (1 - metallic_) + schlickFresnel(r0_, std::abs(cosI)) * metallic_;
  }
  // The normal-incidence reflectance of a dielectric of index eta in air, ((eta - 1) /
  // (eta + 1))^2, from which the material derives r0.
  static Float r0FromEta(Float eta) {
    Float r = (eta - 1) / (eta + 1);
    return r * r;
  }

 private:
  Spectrum r0_;
  Float metallic_, eta_;
  bool twoSided_;
};

}  // namespace candela
