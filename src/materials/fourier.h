// "fourier" (pbrt-v3: string bsdffile): a BSDF tabulated as Fourier series in the azimuth
// (pbrt 3e §8.6; reflection/fourier_bsdf_table.h). The table is shared between materials naming
// the same file. pbrt-v3 gives the BSDF no index of refraction of its own (eta 1): the table's
// eta only scales the transmitted radiance.
#pragma once

#include <memory>

#include "materials/material.h"
#include "reflection/fourier_bsdf_table.h"

namespace candela {

class MaterialInputs;

class FourierMaterial : public Material {
 public:
  FourierMaterial(std::shared_ptr<const FourierBsdfTable> table,
                  const Texture<Float>* bump = nullptr)
      : Material(bump), table_(std::move(table)) {}
  const BSDF* getBSDF(const SurfaceInteraction& si, MemoryArena& arena) const override;

 private:
  std::shared_ptr<const FourierBsdfTable> table_;
};

// The material of a Material "fourier" statement (materials/material_plugins.cpp).
std::unique_ptr<Material> createFourierMaterial(MaterialInputs& in);

}  // namespace candela
