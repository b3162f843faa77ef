// "uber" (pbrt-v2 defaults Kd .25, Ks .25, Kr 0, roughness .1, opacity 1, index 1.5): plastic's
// diffuse and glossy lobes plus a Fresnel mirror, all times opacity, and a straight-through
// transmission of 1 - opacity. As in plastic, the dielectric Fresnel terms have air outside and
// the index inside (not the book code's reversed order), and the BSDF's eta stays 1: passing
// straight through bends nothing.
#pragma once

#include "materials/material.h"

namespace candela {

class UberMaterial : public Material {
 public:
  struct Textures {
    const Texture<Spectrum>*kd, *ks, *kr, *opacity;
    const Texture<Float>*roughness, *index;
  };
  explicit UberMaterial(const Textures& t, const Texture<Float>* bump = nullptr)
      : Material(bump), t_(t) {}
  const BSDF* getBSDF(const SurfaceInteraction& si, MemoryArena& arena) const override;
  // Only a constant black Kr with a constant opacity of 1 (the defaults) rules the mirror and the
  // pass-through out.
  bool maybeSpecular() const override;

 private:
  Textures t_;
};

}  // namespace candela
