// "measured" (pbrt-v2: filename): a tabulated isotropic BRDF, either Matusik et al.'s MERL
// binary table or pbrt-v2's irregularly sampled text format (reflection/merl_brdf.h,
// reflection/irregular_brdf.h). The tables are shared between materials naming the same file.
#pragma once

#include <memory>

#include "materials/material.h"
#include "reflection/irregular_brdf.h"
#include "reflection/merl_brdf.h"

namespace candela {

class MaterialInputs;

class MeasuredMaterial : public Material {
 public:
  MeasuredMaterial(std::shared_ptr<const MerlBrdfTable> merl, const Texture<Float>* bump = nullptr)
      : Material(bump), merl_(std::move(merl)) {}
  MeasuredMaterial(std::shared_ptr<const IrregularBrdfTable> irregular,
                   const Texture<Float>* bump = nullptr)
      : Material(bump), irregular_(std::move(irregular)) {}
  const BSDF* getBSDF(const SurfaceInteraction& si, MemoryArena& arena) const override;

 private:
  std::shared_ptr<const MerlBrdfTable> merl_;
  std::shared_ptr<const IrregularBrdfTable> irregular_;
};

// The material of a Material "measured" statement (materials/material_plugins.cpp).
std::unique_ptr<Material> createMeasuredMaterial(MaterialInputs& in);

}  // namespace candela
