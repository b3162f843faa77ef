// Perfect specular reflection and transmission (lrt draft §9.2): delta distributions that only
// sampleF can return; f and pdf are zero for every pair of directions.
#pragma once

#include "reflection/bxdf.h"
#include "reflection/fresnel.h"

namespace candela {

// Mirror reflection scaled by r and a Fresnel function the caller owns (e.g. in the arena).
class SpecularReflection : public BxDF {
 public:
  SpecularReflection(const Spectrum& r, const Fresnel* fresnel)
      : BxDF(BxDFType(kReflection | kSpecular)), r_(r), fresnel_(fresnel) {}
  Spectrum f(const Vector3f&, const Vector3f&) const override { return Spectrum(0); }
  Spectrum sampleF(const Vector3f& wo, Vector3f* wi, const Point2f& u, Float* pdf,
                   BxDFType* sampledType = nullptr) const override;
  Float pdf(const Vector3f&, const Vector3f&) const override { return 0; }
  // The mean over channels of rho_hd: beside SpecularTransmission's weight, a dielectric is
  // sampled by its Fresnel reflectance, as pbrt-v3's FresnelSpecular and Cycles' glass do.
  std::optional<Float> selectionWeight(const Vector3f& wo) const override;
  // rho_hd = r F(cos theta_o) exactly; rho_hh falls back to Monte Carlo.
  Spectrum rho(const Vector3f& wo, std::span<const Point2f>) const override;
  using BxDF::rho;

 private:
  Spectrum r_;
  const Fresnel* fresnel_;
};

// Refraction through a dielectric interface with index etaOutside on the +z side and etaInside on
// the -z side. Radiance is transported, so it scales by (eta_o / eta_i)^2 across the interface,
// eta_o being the index on wo's side (lrt draft §9.2): the BTDF is not symmetric.
class SpecularTransmission : public BxDF {
 public:
  SpecularTransmission(const Spectrum& t, Float etaOutside, Float etaInside)
      : BxDF(BxDFType(kTransmission | kSpecular)), t_(t), fresnel_(etaOutside, etaInside) {}
  Spectrum f(const Vector3f&, const Vector3f&) const override { return Spectrum(0); }
  // *pdf = 0 under total internal reflection.
  Spectrum sampleF(const Vector3f& wo, Vector3f* wi, const Point2f& u, Float* pdf,
                   BxDFType* sampledType = nullptr) const override;
  Float pdf(const Vector3f&, const Vector3f&) const override { return 0; }
  // t (1 - F(cos theta_o)), the mean over channels; 0 under total internal reflection. Without
  // the radiance scaling, which a path undoes where it leaves the dielectric again.
  std::optional<Float> selectionWeight(const Vector3f& wo) const override;
  // rho_hd = t (1 - F) (eta_o / eta_i)^2: more than 1 from the denser side, by the radiance
  // scaling; times (eta_i / eta_o)^2 it is the transmitted fraction of power.
  Spectrum rho(const Vector3f& wo, std::span<const Point2f>) const override;
  using BxDF::rho;

 private:
  // The refracted direction of wo and the index ratio eta_o / eta_i; false under total internal
  // reflection.
  bool refract(const Vector3f& wo, Vector3f* wi, Float* etaRatio) const;

  Spectrum t_;
  FresnelDielectric fresnel_;
};

}  // namespace candela
