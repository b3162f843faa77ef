// "glass" (lrt draft §10.5; pbrt-v2 defaults Kr 1, Kt 1, index 1.5): specular reflection and
// transmission through a smooth dielectric with the index inside, 1 outside; the BSDF carries
// the index for the integrators' radiance bookkeeping, and picks reflection or refraction by the
// Fresnel term (their selection weights), as pbrt-v3's FresnelSpecular does, not half and half
// as the books' BSDF does. pbrt-v3's glass (also uroughness and vroughness, default 0,
// remaproughness; "eta" as another name for "index") is rough where either roughness is
// non-zero: Trowbridge-Reitz microfacet reflection and refraction (pbrt 3e §9.2, Walter et al.
// 2007) as one BxDF that chooses by the Fresnel term of the microfacet it draws.
#pragma once

#include <memory>

#include <optional>

#include "materials/material.h"
#include "materials/trowbridge_reitz_roughness.h"

namespace candela {

class MaterialInputs;

class GlassMaterial : public Material {
 public:
  GlassMaterial(const Texture<Spectrum>* kr, const Texture<Spectrum>* kt,
                const Texture<Float>* index, const Texture<Float>* bump = nullptr)
      : Material(bump), kr_(kr), kt_(kt), index_(index) {}
  // pbrt-v3's model.
  GlassMaterial(const Texture<Spectrum>* kr, const Texture<Spectrum>* kt,
                const Texture<Float>* index, const TrowbridgeReitzRoughness& roughness,
                const Texture<Float>* bump = nullptr)
      : Material(bump), kr_(kr), kt_(kt), index_(index), trowbridgeReitz_(roughness) {}
  const BSDF* getBSDF(const SurfaceInteraction& si, MemoryArena& arena) const override;
  bool maybeSpecular() const override { return true; }

 private:
  const Texture<Spectrum>*kr_, *kt_;
  const Texture<Float>* index_;
  std::optional<TrowbridgeReitzRoughness> trowbridgeReitz_;
};

// The material of a Material "glass" statement (materials/material_plugins.cpp).
std::unique_ptr<Material> createGlassMaterial(MaterialInputs& in);

}  // namespace candela
