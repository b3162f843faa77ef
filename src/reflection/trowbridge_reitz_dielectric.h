// A rough dielectric interface as one BxDF: Trowbridge-Reitz microfacet reflection and refraction
// (Walter et al. 2007) that draws a visible microfacet normal first and then reflects with the
// probability of that microfacet's Fresnel reflectance, refracting otherwise (Walter et al. 2007
// §5.3; pbrt 4e §9.7's dielectric). Its value is that of TrowbridgeReitzReflection plus
// TrowbridgeReitzTransmission; only the sampling differs from the pair chosen half and half (pbrt
// 3e's rough glass): each sample's value over its density is G / G1 <= 1 times the tint, where
// half-and-half picks weigh 2F and 2(1 - F).
#pragma once

#include "reflection/trowbridge_reitz_bxdfs.h"

namespace candela {

class TrowbridgeReitzDielectric : public BxDF {
 public:
  // r and t tint reflection and refraction (pbrt-v3's Kr and Kt); the choice at a microfacet is
  // by F times r and (1 - F) times t, each averaged over channels. The distribution is the
  // caller's (typically in the arena).
  TrowbridgeReitzDielectric(const Spectrum& r, const Spectrum& t,
                            const TrowbridgeReitzDistribution* distribution, Float etaOutside,
                            Float etaInside)
      : BxDF(BxDFType(kReflection | kTransmission | kGlossy)),
        fresnel_(etaOutside, etaInside),
        reflection_(r, &fresnel_, distribution),
        transmission_(t, distribution, etaOutside, etaInside),
        distribution_(distribution),
        rMean_(std::max(Float(0), r.average())),
        tMean_(std::max(Float(0), t.average())) {}
  TrowbridgeReitzDielectric(const TrowbridgeReitzDielectric&) = delete;
  TrowbridgeReitzDielectric& operator=(const TrowbridgeReitzDielectric&) = delete;

  Spectrum f(const Vector3f& wo, const Vector3f& wi) const override;
  Float pdf(const Vector3f& wo, const Vector3f& wi) const override;
  bool choosesLobe() const override { return true; }
  Spectrum sampleChoosing(const Vector3f& wo, Vector3f* wi, Float uChoice, const Point2f& u,
                          Float* pdf, BxDFType* sampledType = nullptr) const override;
  // Without a third value the choice takes one hashed from u's bits (for rho's estimates).
  Spectrum sampleF(const Vector3f& wo, Vector3f* wi, const Point2f& u, Float* pdf,
                   BxDFType* sampledType = nullptr) const override;

 private:
  // The probability of reflecting at microfacet normal wh (on wo's side, wo . wh > 0); -1 when
  // neither lobe can take the sample (untinted reflection under total internal reflection).
  Float reflectProbability(const Vector3f& wo, const Vector3f& wh) const;

  FresnelDielectric fresnel_;  // before reflection_, which points to it
  TrowbridgeReitzReflection reflection_;
  TrowbridgeReitzTransmission transmission_;
  const TrowbridgeReitzDistribution* distribution_;
  Float rMean_, tMean_;
};

}  // namespace candela
