// "matte": Lambertian when sigma is 0, Oren-Nayar otherwise (lrt draft §10.2).
#pragma once

#include <memory>

#include "materials/material.h"
#include "reflection/oren_nayar.h"

namespace candela {

class MaterialInputs;

class MatteMaterial : public Material {
 public:
  MatteMaterial(const Texture<Spectrum>* kd, const Texture<Float>* sigma,
                const Texture<Float>* bump = nullptr);
  const BSDF* getBSDF(const SurfaceInteraction& si, MemoryArena& arena) const override;

 private:
  // The BSDF at si when constant_.
  const BSDF* constantBSDF(const SurfaceInteraction& si, MemoryArena& arena) const;
  // Any other case. Kept out of getBSDF, whose common constant case then needs no stack frame
  // (the room for a bumped copy of the point and the saved registers were ~15 of its ~120
  // instructions per hit).
  [[gnu::noinline]] const BSDF* bumpedOrTexturedBSDF(const SurfaceInteraction& si,
                                                     MemoryArena& arena) const;

  const Texture<Spectrum>* kd_;
  const Texture<Float>* sigma_;
  // With constant Kd and sigma the BxDF is the same at every point: made once here and shared by
  // every BSDF (BxDFs are immutable), instead of two texture lookups and an arena BxDF per hit.
  // constant_ with neither set: Kd is black, no component.
  bool constant_ = false;
  std::unique_ptr<const LambertianReflection> constantLambertian_;
  std::unique_ptr<const OrenNayar> constantOrenNayar_;
};

// The material of a Material "matte" statement (materials/material_plugins.cpp).
std::unique_ptr<Material> createMatteMaterial(MaterialInputs& in);

}  // namespace candela
