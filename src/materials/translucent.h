// "translucent" (lrt draft §10.4; pbrt-v2 defaults Kd .25, Ks .25, reflect .5, transmit .5,
// roughness .1, index 1.5): plastic's diffuse and glossy lobes, each both reflected (times
// reflect) and mirrored to the other side (times transmit). Black terms are skipped. The coat's
// Fresnel term is air outside, the index inside (the book code's reversed order is a defect; see
// plastic.h), and the BSDF carries the index. pbrt-v3's translucent (same defaults,
// remaproughness; pbrt 3e §9.2) uses a Trowbridge-Reitz distribution for the glossy lobes, and
// its glossy transmission is true microfacet refraction into the index, not a mirrored lobe.
#pragma once

#include <memory>

#include <optional>

#include "materials/material.h"
#include "materials/trowbridge_reitz_roughness.h"

namespace candela {

class MaterialInputs;

class TranslucentMaterial : public Material {
 public:
  TranslucentMaterial(const Texture<Spectrum>* kd, const Texture<Spectrum>* ks,
                      const Texture<Spectrum>* reflect, const Texture<Spectrum>* transmit,
                      const Texture<Float>* roughness, Float index,
                      const Texture<Float>* bump = nullptr)
      : Material(bump),
        kd_(kd),
        ks_(ks),
        reflect_(reflect),
        transmit_(transmit),
        roughness_(roughness),
        index_(index) {}
  // pbrt-v3's model.
  TranslucentMaterial(const Texture<Spectrum>* kd, const Texture<Spectrum>* ks,
                      const Texture<Spectrum>* reflect, const Texture<Spectrum>* transmit,
                      const TrowbridgeReitzRoughness& roughness, Float index,
                      const Texture<Float>* bump = nullptr)
      : TranslucentMaterial(kd, ks, reflect, transmit, roughness.u, index, bump) {
    trowbridgeReitz_ = roughness;
  }
  const BSDF* getBSDF(const SurfaceInteraction& si, MemoryArena& arena) const override;

 private:
  const Texture<Spectrum>*kd_, *ks_, *reflect_, *transmit_;
  const Texture<Float>* roughness_;
  Float index_;
  std::optional<TrowbridgeReitzRoughness> trowbridgeReitz_;
};

// The material of a Material "translucent" statement (materials/material_plugins.cpp).
std::unique_ptr<Material> createTranslucentMaterial(MaterialInputs& in);

}  // namespace candela
