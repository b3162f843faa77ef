// "mix" (pbrt-v2: amount .5, namedmaterial1, namedmaterial2): the BxDFs of the first material
// times amount plus those of the second times 1 - amount, amount a spectrum texture clamped to
// [0, 1]. pbrt-v2 weights the *first* material by amount (pbrt-v4 reversed it). The mixed BSDF
// uses the frame at the point and the first material's eta; bump maps of the two materials are
// not applied (one BSDF has one shading frame).
#pragma once

#include <memory>

#include "materials/material.h"

namespace candela {

class MaterialInputs;

class MixMaterial : public Material {
 public:
  MixMaterial(const Material* m1, const Material* m2, const Texture<Spectrum>* amount)
      : m1_(m1), m2_(m2), amount_(amount) {}
  const BSDF* getBSDF(const SurfaceInteraction& si, MemoryArena& arena) const override;
  bool maybeSpecular() const override { return m1_->maybeSpecular() || m2_->maybeSpecular(); }

 private:
  const Material *m1_, *m2_;
  const Texture<Spectrum>* amount_;
};

// The material of a Material "mix" statement (materials/material_plugins.cpp).
std::unique_ptr<Material> createMixMaterial(MaterialInputs& in);

}  // namespace candela
