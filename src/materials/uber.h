// "uber" (pbrt-v2 defaults Kd .25, Ks .25, Kr 0, roughness .1, opacity 1, index 1.5): plastic's
// diffuse and glossy lobes plus a Fresnel mirror, all times opacity, and a straight-through
// transmission of 1 - opacity. As in plastic, the dielectric Fresnel terms have air outside and
// the index inside (not the book code's reversed order), and the BSDF's eta stays 1: passing
// straight through bends nothing.
//
// pbrt-v3's uber (pbrt 3e §9.2; also Kt 0, uroughness and vroughness overriding roughness,
// remaproughness, "eta" as another name for "index") has a Trowbridge-Reitz glossy lobe, adds a
// specular refraction Kt into the index, and its BSDF carries the index unless the surface is
// partly transparent.
#pragma once

#include <memory>

#include <optional>

#include "materials/material.h"
#include "materials/trowbridge_reitz_roughness.h"

namespace candela {

class MaterialInputs;

class UberMaterial : public Material {
 public:
  struct Textures {
    const Texture<Spectrum>*kd, *ks, *kr, *opacity;
    const Texture<Float>*roughness, *index;
    const Texture<Spectrum>* kt = nullptr;  // pbrt-v3 only
  };
  explicit UberMaterial(const Textures& t, const Texture<Float>* bump = nullptr)
      : Material(bump), t_(t) {}
  // pbrt-v3's model; t.roughness is unused (roughness gives the u and v textures).
  UberMaterial(const Textures& t, const TrowbridgeReitzRoughness& roughness,
               const Texture<Float>* bump = nullptr)
      : Material(bump), t_(t), trowbridgeReitz_(roughness) {}
  const BSDF* getBSDF(const SurfaceInteraction& si, MemoryArena& arena) const override;
  // Only a constant black Kr (and Kt) with a constant opacity of 1 (the defaults) rules the
  // mirror and the pass-through out.
  bool maybeSpecular() const override;

 private:
  Textures t_;
  std::optional<TrowbridgeReitzRoughness> trowbridgeReitz_;
};

// The material of a Material "uber" statement (materials/material_plugins.cpp).
std::unique_ptr<Material> createUberMaterial(MaterialInputs& in);

}  // namespace candela
