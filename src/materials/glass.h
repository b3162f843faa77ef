// "glass" (lrt draft §10.5; pbrt-v2 defaults Kr 1, Kt 1, index 1.5): specular reflection and
// transmission through a smooth dielectric with the index inside, 1 outside; the BSDF carries
// the index for the integrators' radiance bookkeeping.
#pragma once

#include "materials/material.h"

namespace candela {

class GlassMaterial : public Material {
 public:
  GlassMaterial(const Texture<Spectrum>* kr, const Texture<Spectrum>* kt,
                const Texture<Float>* index, const Texture<Float>* bump = nullptr)
      : Material(bump), kr_(kr), kt_(kt), index_(index) {}
  const BSDF* getBSDF(const SurfaceInteraction& si, MemoryArena& arena) const override;
  bool maybeSpecular() const override { return true; }

 private:
  const Texture<Spectrum>*kr_, *kt_;
  const Texture<Float>* index_;
};

}  // namespace candela
