// Torrance-Sparrow microfacet reflection (lrt draft §9.4.2): mirror microfacets with normal
// distribution D, V-groove masking and shadowing G, and a Fresnel term,
// f = R D(wh) G(wo, wi) F(wi . wh) / (4 cos theta_o cos theta_i). Sampled through the
// distribution (lrt draft §15.3).
#pragma once

#include "reflection/bxdf.h"
#include "reflection/fresnel.h"
#include "reflection/microfacet_distribution.h"

namespace candela {

// The V-groove geometric attenuation (lrt draft §9.4.2):
// G = min(1, 2 |n.wh| |n.wo| / |wo.wh|, 2 |n.wh| |n.wi| / |wo.wh|).
Float vGrooveG(const Vector3f& wo, const Vector3f& wi, const Vector3f& wh);

// The Fresnel function and distribution are owned by the caller (typically the same arena).
class MicrofacetReflection : public BxDF {
 public:
  MicrofacetReflection(const Spectrum& r, const Fresnel* fresnel,
                       const MicrofacetDistribution* distribution)
      : BxDF(BxDFType(kReflection | kGlossy)),
        r_(r),
        fresnel_(fresnel),
        distribution_(distribution) {}
  Spectrum f(const Vector3f& wo, const Vector3f& wi) const override;
  // *pdf = 0 when the reflected direction falls on the other side of the surface.
  Spectrum sampleF(const Vector3f& wo, Vector3f* wi, const Point2f& u, Float* pdf,
                   BxDFType* sampledType = nullptr) const override;
  Float pdf(const Vector3f& wo, const Vector3f& wi) const override;

 private:
  Spectrum r_;
  const Fresnel* fresnel_;
  const MicrofacetDistribution* distribution_;
};

}  // namespace candela
