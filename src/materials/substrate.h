// "substrate" (lrt draft §10.8; pbrt-v2 defaults Kd .5, Ks .5, uroughness .1, vroughness .1):
// Ashikhmin and Shirley's coated diffuse model (FresnelBlend) with the anisotropic distribution,
// exponents 1 / uroughness along dp/du and 1 / vroughness along dp/dv.
#pragma once

#include "materials/material.h"

namespace candela {

class SubstrateMaterial : public Material {
 public:
  SubstrateMaterial(const Texture<Spectrum>* kd, const Texture<Spectrum>* ks,
                    const Texture<Float>* uRoughness, const Texture<Float>* vRoughness,
                    const Texture<Float>* bump = nullptr)
      : Material(bump), kd_(kd), ks_(ks), uRoughness_(uRoughness), vRoughness_(vRoughness) {}
  const BSDF* getBSDF(const SurfaceInteraction& si, MemoryArena& arena) const override;

 private:
  const Texture<Spectrum>*kd_, *ks_;
  const Texture<Float>*uRoughness_, *vRoughness_;
};

}  // namespace candela
