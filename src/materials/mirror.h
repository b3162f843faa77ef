// "mirror" (lrt draft §10.6; pbrt-v2 default Kr .9): perfect specular reflection of Kr at every
// angle (no Fresnel falloff).
#pragma once

#include <memory>

#include "materials/material.h"

namespace candela {

class MaterialInputs;

class MirrorMaterial : public Material {
 public:
  explicit MirrorMaterial(const Texture<Spectrum>* kr, const Texture<Float>* bump = nullptr)
      : Material(bump), kr_(kr) {}
  const BSDF* getBSDF(const SurfaceInteraction& si, MemoryArena& arena) const override;
  bool maybeSpecular() const override { return true; }

 private:
  const Texture<Spectrum>* kr_;
};

// The material of a Material "mirror" statement (materials/material_plugins.cpp).
std::unique_ptr<Material> createMirrorMaterial(MaterialInputs& in);

}  // namespace candela
