// Disney's clearcoat (Burley 2012, §5.4 and its Appendix B.2): a second, fixed specular lobe for
// a clear lacquer of index 1.5 over the base, with the long-tailed GTR1 distribution,
// Schlick's Fresnel with R0 = 0.04 (index 1.5) and Smith's GGX masking for a fixed alpha of
// 0.25 (separable G = G1(wo) G1(wi), as in the paper):
//   f = weight / 4 * D(wh) F(wi . wh) G / (4 |cos theta_o| |cos theta_i|),
// the 1/4 being the paper's scale that keeps the coat at most a quarter of a full specular lobe.
// gloss in [0, 1] maps to D's alpha = lerp(gloss, 0.1, 0.001) (0: satin, 1: gloss). Sampled
// through D (not the visible normals), wi mirrored about the half vector.
#pragma once

#include "reflection/bxdf.h"
#include "reflection/gtr1_distribution.h"
#include "reflection/trowbridge_reitz.h"

namespace candela {

class DisneyClearcoat : public BxDF {
 public:
  DisneyClearcoat(Float weight, Float gloss);
  Spectrum f(const Vector3f& wo, const Vector3f& wi) const override;
  // *pdf = 0 when the mirrored direction falls on the other side of the surface.
  Spectrum sampleF(const Vector3f& wo, Vector3f* wi, const Point2f& u, Float* pdf,
                   BxDFType* sampledType = nullptr) const override;
  Float pdf(const Vector3f& wo, const Vector3f& wi) const override;

  static Float glossToAlpha(Float gloss) { return lerp(gloss, Float(0.1), Float(0.001)); }

 private:
  Float weight_;
  Gtr1Distribution distribution_;
  TrowbridgeReitzDistribution masking_;
};

}  // namespace candela
