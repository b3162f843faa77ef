// "substrate" (lrt draft §10.8; pbrt-v2 defaults Kd .5, Ks .5, uroughness .1, vroughness .1):
// Ashikhmin and Shirley's coated diffuse model (FresnelBlend) with the anisotropic distribution,
// exponents 1 / uroughness along dp/du and 1 / vroughness along dp/dv. pbrt-v3's substrate
// (same defaults, remaproughness) is the same coat over the Trowbridge-Reitz distribution with
// alphas along dp/du and dp/dv (pbrt 3e §9.2.4).
#pragma once

#include <memory>

#include <optional>

#include "materials/material.h"
#include "materials/trowbridge_reitz_roughness.h"

namespace candela {

class MaterialInputs;

class SubstrateMaterial : public Material {
 public:
  SubstrateMaterial(const Texture<Spectrum>* kd, const Texture<Spectrum>* ks,
                    const Texture<Float>* uRoughness, const Texture<Float>* vRoughness,
                    const Texture<Float>* bump = nullptr)
      : Material(bump), kd_(kd), ks_(ks), uRoughness_(uRoughness), vRoughness_(vRoughness) {}
  // pbrt-v3's model.
  SubstrateMaterial(const Texture<Spectrum>* kd, const Texture<Spectrum>* ks,
                    const TrowbridgeReitzRoughness& roughness, const Texture<Float>* bump = nullptr)
      : Material(bump),
        kd_(kd),
        ks_(ks),
        uRoughness_(roughness.u),
        vRoughness_(roughness.v),
        trowbridgeReitz_(roughness) {}
  const BSDF* getBSDF(const SurfaceInteraction& si, MemoryArena& arena) const override;

 private:
  const Texture<Spectrum>*kd_, *ks_;
  const Texture<Float>*uRoughness_, *vRoughness_;
  std::optional<TrowbridgeReitzRoughness> trowbridgeReitz_;
};

// The material of a Material "substrate" statement (materials/material_plugins.cpp).
std::unique_ptr<Material> createSubstrateMaterial(MaterialInputs& in);

}  // namespace candela
