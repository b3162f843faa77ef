// Ashikhmin and Shirley's glossy coat over a diffuse base (lrt draft §9.6, Ashikhmin and Shirley
// 2000): a reciprocal, energy-conserving pair of a Schlick-Fresnel microfacet lobe and a diffuse
// term that loses what the coat reflects.
#pragma once

#include "reflection/bxdf.h"
#include "reflection/microfacet_distribution.h"

namespace candela {

// specular = p_h(wh) F_schlick(wi . wh) / (4 |wi . wh| max(|cos theta_i|, |cos theta_o|)) where
// p_h is the distribution's half-vector density, which for Blinn and Ashikhmin-Shirley is their
// paper's sqrt((nu + 1)(nv + 1)) / (2 pi) cos^e theta_h. The draft wrote D / (8 pi ...), right
// only for its unnormalised anisotropic D. diffuse = 28 Rd (1 - Rs) / (23 pi)
// (1 - (1 - |cos theta_i| / 2)^5)(1 - (1 - |cos theta_o| / 2)^5).
class FresnelBlend : public BxDF {
 public:
  FresnelBlend(const Spectrum& rd, const Spectrum& rs, const MicrofacetDistribution* distribution)
      : BxDF(BxDFType(kReflection | kGlossy)), rd_(rd), rs_(rs), distribution_(distribution) {}
  Spectrum f(const Vector3f& wo, const Vector3f& wi) const override;
  // Half the samples cosine-weighted, half through the distribution (lrt draft §15.3.3).
  Spectrum sampleF(const Vector3f& wo, Vector3f* wi, const Point2f& u, Float* pdf,
                   BxDFType* sampledType = nullptr) const override;
  Float pdf(const Vector3f& wo, const Vector3f& wi) const override;
  Spectrum schlickFresnel(Float cosTheta) const;

 private:
  Spectrum rd_, rs_;
  const MicrofacetDistribution* distribution_;
};

}  // namespace candela
