// "subsurface" and "kdsubsurface" (pbrt 2e §16.5; pbrt-v2's parameters): a smooth dielectric
// boundary over a scattering medium. The surface BSDF is the specular part only, Fresnel
// reflection (1 to eta) scaled by Kr; the light scattered inside comes back through the dipole
// BSSRDF that "dipolesubsurface" adds from subsurface() (other integrators see only the specular
// reflection, as in pbrt-v2).
#pragma once

#include <memory>

#include "materials/material.h"
#include "materials/subsurface_scattering.h"

namespace candela {

class MaterialInputs;

// "subsurface": sigma_a and sigma_prime_s given (per unit length), both multiplied by scale.
class SubsurfaceMaterial : public Material, public SubsurfaceScattering {
 public:
  SubsurfaceMaterial(Float scale, const Texture<Spectrum>* sigmaA,
                     const Texture<Spectrum>* sigmaPrimeS, Float eta, const Texture<Spectrum>* kr,
                     const Texture<Float>* bump = nullptr)
      : Material(bump),
        scale_(scale),
        sigmaA_(sigmaA),
        sigmaPrimeS_(sigmaPrimeS),
        eta_(eta),
        kr_(kr) {}
  const BSDF* getBSDF(const SurfaceInteraction& si, MemoryArena& arena) const override;
  bool maybeSpecular() const override { return true; }
  const SubsurfaceScattering* subsurface() const override { return this; }
  BSSRDFCoefficients coefficients(const SurfaceInteraction& si) const override;

 private:
  Float scale_;
  const Texture<Spectrum>*sigmaA_, *sigmaPrimeS_;
  Float eta_;
  const Texture<Spectrum>* kr_;
};

// "kdsubsurface": the medium whose total diffuse reflectance is Kd (per channel) with mean free
// path meanfreepath, found by inverting the closed form (absorbedFractionForDiffuseReflectance).
class KdSubsurfaceMaterial : public Material, public SubsurfaceScattering {
 public:
  KdSubsurfaceMaterial(const Texture<Spectrum>* kd, const Texture<Float>* meanFreePath, Float eta,
                       const Texture<Spectrum>* kr, const Texture<Float>* bump = nullptr)
      : Material(bump), kd_(kd), meanFreePath_(meanFreePath), eta_(eta), kr_(kr) {}
  const BSDF* getBSDF(const SurfaceInteraction& si, MemoryArena& arena) const override;
  bool maybeSpecular() const override { return true; }
  const SubsurfaceScattering* subsurface() const override { return this; }
  BSSRDFCoefficients coefficients(const SurfaceInteraction& si) const override;

 private:
  const Texture<Spectrum>* kd_;
  const Texture<Float>* meanFreePath_;
  Float eta_;
  const Texture<Spectrum>* kr_;
};

// The materials of Material "subsurface" and "kdsubsurface" statements
// (materials/subsurface_params.cpp; pbrt-v2's parameters and defaults).
std::unique_ptr<Material> createSubsurfaceMaterial(MaterialInputs& in);
std::unique_ptr<Material> createKdSubsurfaceMaterial(MaterialInputs& in);

}  // namespace candela
