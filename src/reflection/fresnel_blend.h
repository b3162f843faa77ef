// Ashikhmin and Shirley's glossy coat over a diffuse base (lrt draft §9.6, Ashikhmin and Shirley
// 2000): a reciprocal, energy-conserving pair of a Schlick-Fresnel microfacet lobe and a diffuse
// term that loses what the coat reflects.
#pragma once

#include "reflection/bxdf.h"
#include "reflection/microfacet_distribution.h"
#include "reflection/trowbridge_reitz.h"

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

// The diffuse term both coats share, 28 Rd (1 - Rs) / (23 pi) (1 - (1 - |cos theta_i| / 2)^5)
// (1 - (1 - |cos theta_o| / 2)^5), and Schlick's Fresnel Rs + (1 - Rs)(1 - cos)^5.
Spectrum fresnelBlendDiffuse(const Spectrum& rd, const Spectrum& rs, Float cosO, Float cosI);
Spectrum schlickFresnel(const Spectrum& rs, Float cosTheta);

// pbrt-v3's FresnelBlend (pbrt 3e §8.5) over the Trowbridge-Reitz distribution: the specular term
// is D(wh) F_schlick(wi . wh) / (4 |wi . wh| max(|cos theta_i|, |cos theta_o|)) with the
// distribution's D, and the glossy half of the samples reflects about visible normals.
class TrowbridgeReitzFresnelBlend : public BxDF {
 public:
  TrowbridgeReitzFresnelBlend(const Spectrum& rd, const Spectrum& rs,
                              const TrowbridgeReitzDistribution* distribution)
      : BxDF(BxDFType(kReflection | kGlossy)), rd_(rd), rs_(rs), distribution_(distribution) {}
  Spectrum f(const Vector3f& wo, const Vector3f& wi) const override;
  // Half the samples cosine-weighted, half through the distribution's visible normals.
  Spectrum sampleF(const Vector3f& wo, Vector3f* wi, const Point2f& u, Float* pdf,
                   BxDFType* sampledType = nullptr) const override;
  Float pdf(const Vector3f& wo, const Vector3f& wi) const override;

 private:
  Spectrum rd_, rs_;
  const TrowbridgeReitzDistribution* distribution_;
};

}  // namespace candela
