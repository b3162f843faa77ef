// lrt's measured Lafortune materials (lrt draft §10.9): a fixed fit, no parameters but the bump
// map. Only "clay" has its coefficients in the draft; the factory rejects the other names.
#pragma once

#include <memory>
#include <string_view>

#include "materials/material.h"
#include "reflection/lafortune.h"

namespace candela {

class MaterialInputs;

class LafortuneMaterial : public Material {
 public:
  explicit LafortuneMaterial(const LafortuneFit& fit, const Texture<Float>* bump = nullptr)
      : Material(bump), fit_(fit) {}
  const BSDF* getBSDF(const SurfaceInteraction& si, MemoryArena& arena) const override;

 private:
  LafortuneFit fit_;  // static data
};

// The material of a Material "clay" statement (materials/material_plugins.cpp).
std::unique_ptr<Material> createClayMaterial(MaterialInputs& in);
// One of the fits the draft names (§10.9) without printing their coefficients.
bool isUnprintedLafortuneFit(std::string_view name);

}  // namespace candela
