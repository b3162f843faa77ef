// Phase functions (lrt draft §12.1; pbrt 2e §11.1): the angular distribution of light scattered
// at a point in a medium, a density over the sphere of directions that integrates to 1.
//
// Both directions point away from the scattering point (pbrt 3e's convention): wo toward where
// the light goes next (the camera side), wi toward where it came from (the light side). The
// scattering angle θ is the angle between the light's direction of travel before (-wi) and after
// (wo), so cos θ = -dot(wo, wi); g > 0 scatters forward (θ small).
#pragma once

#include "core/vector.h"

namespace candela {

class PhaseFunction {
 public:
  enum class Kind { Isotropic, HenyeyGreenstein, Schlick, Rayleigh, MieHazy, MieMurky };

  // Isotropic by default.
  PhaseFunction() = default;
  static PhaseFunction isotropic() { return PhaseFunction(); }
  // g in (-1, 1): the mean cosine of the scattering angle.
  static PhaseFunction henyeyGreenstein(Float g);
  // Schlick's approximation of Henyey–Greenstein with k = 1.55 g - 0.55 g^3 (pbrt 2e §11.1.1).
  static PhaseFunction schlick(Float g);
  static PhaseFunction rayleigh() { return PhaseFunction(Kind::Rayleigh, 0); }
  // Nishita et al.'s fits to Mie scattering by hazy and murky atmospheres (pbrt 2e §11.1.1).
  static PhaseFunction mieHazy() { return PhaseFunction(Kind::MieHazy, 0); }
  static PhaseFunction mieMurky() { return PhaseFunction(Kind::MieMurky, 0); }

  Kind kind() const { return kind_; }
  // g for Henyey–Greenstein and Schlick, 0 otherwise.
  Float g() const { return g_; }

  // The density per steradian at scattering angle θ.
  Float evaluate(Float cosTheta) const;
  Float p(const Vector3f& wo, const Vector3f& wi) const { return evaluate(-dot(wo, wi)); }
  // Samples wi (unit) given wo (unit); *pdf is the density of the sample per steradian; returns
  // p(wo, wi) / pdf, which is exactly 1 for isotropic, Henyey–Greenstein and Schlick (sampled by
  // inverting their distributions) and the ratio for Rayleigh and Mie (sampled uniformly).
  Float sample(const Vector3f& wo, const Point2f& u, Vector3f* wi, Float* pdf) const;
  Float pdf(const Vector3f& wo, const Vector3f& wi) const;

 private:
  PhaseFunction(Kind kind, Float g) : kind_(kind), g_(g) {}
  Kind kind_ = Kind::Isotropic;
  Float g_ = 0;
};

}  // namespace candela
