// "matte": Lambertian when sigma is 0, Oren-Nayar otherwise (lrt draft §10.2).
#pragma once

#include "materials/material.h"

namespace candela {

class MatteMaterial : public Material {
 public:
  MatteMaterial(const Texture<Spectrum>* kd, const Texture<Float>* sigma,
                const Texture<Float>* bump = nullptr)
      : Material(bump), kd_(kd), sigma_(sigma) {}
  const BSDF* getBSDF(const SurfaceInteraction& si, MemoryArena& arena) const override;

 private:
  const Texture<Spectrum>* kd_;
  const Texture<Float>* sigma_;
};

}  // namespace candela
