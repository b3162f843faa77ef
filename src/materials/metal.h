// "metal" (pbrt-v2; roughness .01): a Blinn microfacet conductor with complex index eta + i k,
// spectrum textures. pbrt-v2's defaults are copper's measured n and k; candela renders RGB, so
// they are copper's values at red, green and blue (about 650, 550 and 450 nm).
#pragma once

#include "materials/material.h"

namespace candela {

namespace copper {
inline constexpr Spectrum kEta(0.200438f, 0.924033f, 1.10221f);
inline constexpr Spectrum kK(3.91295f, 2.45285f, 2.14219f);
}  // namespace copper

class MetalMaterial : public Material {
 public:
  MetalMaterial(const Texture<Spectrum>* eta, const Texture<Spectrum>* k,
                const Texture<Float>* roughness, const Texture<Float>* bump = nullptr)
      : Material(bump), eta_(eta), k_(k), roughness_(roughness) {}
  const BSDF* getBSDF(const SurfaceInteraction& si, MemoryArena& arena) const override;

 private:
  const Texture<Spectrum>*eta_, *k_;
  const Texture<Float>* roughness_;
};

}  // namespace candela
