// pbrt-v3's microfacet BxDFs over the Trowbridge-Reitz distribution with Smith masking (pbrt 3e
// §8.4.4): Torrance-Sparrow reflection and its transmission counterpart (Walter et al. 2007),
// both sampled through the visible normals (pbrt 3e §14.1.1). They differ from pbrt-v2's
// MicrofacetReflection (reflection/microfacet.h) in G, the distribution and the sampling.
#pragma once

#include "reflection/bxdf.h"
#include "reflection/fresnel.h"
#include "reflection/trowbridge_reitz.h"

namespace candela {

// f = R D(wh) G(wo, wi) F(wi . wh) / (4 |cos theta_o| |cos theta_i|), wh = normalize(wo + wi).
// The Fresnel function and the distribution are owned by the caller (typically the arena).
class TrowbridgeReitzReflection : public BxDF {
 public:
  TrowbridgeReitzReflection(const Spectrum& r, const Fresnel* fresnel,
                            const TrowbridgeReitzDistribution* distribution)
      : BxDF(BxDFType(kReflection | kGlossy)),
        r_(r),
        fresnel_(fresnel),
        distribution_(distribution) {}
  Spectrum f(const Vector3f& wo, const Vector3f& wi) const override;
  Spectrum sampleF(const Vector3f& wo, Vector3f* wi, const Point2f& u, Float* pdf,
                   BxDFType* sampledType = nullptr) const override;
  // The visible-normal density over 4 |wo . wh|, the Jacobian of reflection (pbrt 3e §14.1.1).
  Float pdf(const Vector3f& wo, const Vector3f& wi) const override;

 private:
  Spectrum r_;
  const Fresnel* fresnel_;
  const TrowbridgeReitzDistribution* distribution_;
};

// Refraction through rough dielectric microfacets, index etaOutside on the +z side and etaInside
// on the -z side. With eta = eta_i / eta_o (the index on wi's side over wo's) and the generalised
// half vector wh = normalize(wo + eta wi):
//   f = T (1 - F(wo . wh)) D G |wi . wh| |wo . wh| / (|cos theta_o| |cos theta_i|
//       (wo . wh + eta wi . wh)^2),
// which carries radiance: it already includes the (eta_o / eta_i)^2 scaling that pbrt 3e §8.4.4
// applies in radiance mode, as SpecularTransmission does. Only pairs that a microfacet facing wo
// can refract count (wo . wh > 0 > wi . wh with wh on wo's side).
class TrowbridgeReitzTransmission : public BxDF {
 public:
  TrowbridgeReitzTransmission(const Spectrum& t, const TrowbridgeReitzDistribution* distribution,
                              Float etaOutside, Float etaInside)
      : BxDF(BxDFType(kTransmission | kGlossy)),
        t_(t),
        distribution_(distribution),
        fresnel_(etaOutside, etaInside) {}
  Spectrum f(const Vector3f& wo, const Vector3f& wi) const override;
  // *pdf = 0 under total internal reflection at the sampled microfacet.
  Spectrum sampleF(const Vector3f& wo, Vector3f* wi, const Point2f& u, Float* pdf,
                   BxDFType* sampledType = nullptr) const override;
  // The visible-normal density times dwh / dwi = eta^2 |wi . wh| / (wo . wh + eta wi . wh)^2.
  Float pdf(const Vector3f& wo, const Vector3f& wi) const override;
  // The half vector on wo's side for a refracted pair, or false if no microfacet facing wo
  // refracts wo into wi.
  bool halfVector(const Vector3f& wo, const Vector3f& wi, Vector3f* wh) const;

 private:
  // eta_i / eta_o for wo on its side of the surface.
  Float etaRatio(const Vector3f& wo) const {
    return wo.z > 0 ? fresnel_.etaInside() / fresnel_.etaOutside()
                    : fresnel_.etaOutside() / fresnel_.etaInside();
  }

  Spectrum t_;
  const TrowbridgeReitzDistribution* distribution_;
  FresnelDielectric fresnel_;
};

}  // namespace candela
