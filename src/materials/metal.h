// "metal" (pbrt-v2; roughness .01): a Blinn microfacet conductor with complex index eta + i k,
// spectrum textures. pbrt-v2's defaults are copper's measured n and k; candela renders RGB, so
// they are copper's values at red, green and blue (about 650, 550 and 450 nm). pbrt-v3's metal
// (same defaults; uroughness and vroughness override roughness, remaproughness) is the same
// conductor over the Trowbridge-Reitz distribution with Smith masking (pbrt 3e §9.2.3).
#pragma once

#include <memory>

#include <optional>

#include "materials/material.h"
#include "materials/trowbridge_reitz_roughness.h"

namespace candela {

class MaterialInputs;

namespace copper {
inline constexpr Spectrum kEta(0.200438f, 0.924033f, 1.10221f);
inline constexpr Spectrum kK(3.91295f, 2.45285f, 2.14219f);
}  // namespace copper

class MetalMaterial : public Material {
 public:
  MetalMaterial(const Texture<Spectrum>* eta, const Texture<Spectrum>* k,
                const Texture<Float>* roughness, const Texture<Float>* bump = nullptr)
      : Material(bump), eta_(eta), k_(k), roughness_(roughness) {}
  // pbrt-v3's model.
  MetalMaterial(const Texture<Spectrum>* eta, const Texture<Spectrum>* k,
                const TrowbridgeReitzRoughness& roughness, const Texture<Float>* bump = nullptr)
      : Material(bump), eta_(eta), k_(k), roughness_(nullptr), trowbridgeReitz_(roughness) {}
  const BSDF* getBSDF(const SurfaceInteraction& si, MemoryArena& arena) const override;

 private:
  const Texture<Spectrum>*eta_, *k_;
  const Texture<Float>* roughness_;  // pbrt-v2's Blinn roughness
  std::optional<TrowbridgeReitzRoughness> trowbridgeReitz_;
};

// The material of a Material "metal" statement (materials/material_plugins.cpp).
std::unique_ptr<Material> createMetalMaterial(MaterialInputs& in);

}  // namespace candela
