// The dipole diffusion approximation of multiple subsurface scattering (Jensen, Marschner, Levoy
// and Hanrahan 2001, "A Practical Model for Subsurface Light Transport"; pbrt 2e §16.5): light
// entering a semi-infinite homogeneous medium at distance r from where it leaves is reflected with
// the diffuse reflectance profile Rd(r) of a real source below the surface and a negative virtual
// source above it, placed so the fluence vanishes at the extrapolated boundary.
#pragma once

#include "core/spectrum.h"

namespace candela {

// What the dipole needs to know about a medium: absorption sigma_a and reduced scattering
// sigma_s' = sigma_s (1 - g) (per unit length, per channel), and the relative index of refraction
// eta of the medium to the outside.
struct BSSRDFCoefficients {
  Spectrum sigmaA;
  Spectrum sigmaPrimeS;
  Float eta = 1.33f;
};

// The average Fresnel reflectance of diffuse light at the boundary seen from outside, by the
// polynomial fit Jensen et al. 2001 (eq. 5, after Egan and Hilgeman) use:
// Fdr = -1.440/eta^2 + 0.710/eta + 0.668 + 0.0636 eta.
Float diffuseFresnelReflectance(Float eta);

// The boundary term A = (1 + Fdr) / (1 - Fdr) that moves the virtual source (Jensen et al. 2001).
Float dipoleBoundaryA(Float eta);

// The total diffuse reflectance, the integral of Rd(r) 2 pi r dr over the plane, in closed form
// (Jensen et al. 2001 eq. 6 integrated; pbrt 2e §16.5):
// Rd = (a'/2) (1 + exp(-(4/3) A sqrt(3 (1 - a')))) exp(-sqrt(3 (1 - a'))), a' the reduced albedo.
Float totalDiffuseReflectance(Float reducedAlbedo, Float A);

// The same with the absorbed fraction 1 - a' = sigma_a / sigma_t' given instead, which keeps its
// precision where a' is close to 1 (there Rd depends on sqrt(1 - a')).
Float totalDiffuseReflectanceOfAbsorption(Float absorbedFraction, Float A);

// The inverse: the absorbed fraction 1 - a' in [0, 1] whose total diffuse reflectance is rd
// (clamped to [0, 1]), by bisection in double on the closed form, which falls monotonically from
// 1 at 1 - a' = 0 to 0 at 1 - a' = 1. Accuracy: the root to 1e-12, so that
// |totalDiffuseReflectanceOfAbsorption(result, A) - rd| < 1e-6 for rd in [0.01, 0.99] in Float
// (the tests check 1e-6).
Float absorbedFractionForDiffuseReflectance(Float rd, Float A);

// pbrt-v2's kdsubsurface parameterisation (pbrt 2e §16.5): the coefficients whose total diffuse
// reflectance is kd per channel when the mean free path 1 / sigma_t' is meanFreePath.
BSSRDFCoefficients coefficientsFromDiffuse(const Spectrum& kd, Float meanFreePath, Float eta);

// Rd(r) per channel for one medium, with the per-channel constants precomputed.
class DipoleProfile {
 public:
  explicit DipoleProfile(const BSSRDFCoefficients& c);
  // The diffuse reflectance profile at squared distance r2 between entry and exit points
  // (Jensen et al. 2001 eq. 4):
  // Rd(r) = a'/(4 pi) [ zr (sigma_tr dr + 1) e^(-sigma_tr dr) / dr^3
  //                    + zv (sigma_tr dv + 1) e^(-sigma_tr dv) / dv^3 ],
  // dr = sqrt(r^2 + zr^2), dv = sqrt(r^2 + zv^2), zr = 1/sigma_t', zv = zr (1 + 4A/3).
  Spectrum Rd(Float r2) const;
  // The closed form of the integral of Rd over the plane (for the tests and reports).
  Spectrum totalReflectance() const;
  Float eta() const { return eta_; }

 private:
  Float albedo_[3], absorbed_[3], sigmaTr_[3], zr_[3], zv_[3];
  Float A_, eta_;
};

}  // namespace candela
