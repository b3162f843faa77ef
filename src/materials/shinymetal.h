// "shinymetal" (lrt draft §10.7; pbrt-v2 defaults Ks 1, Kr 1, roughness .1): a glossy Blinn lobe
// and a mirror lobe, each a conductor with k = 0 whose index is fitted so that its
// normal-incidence reflectance is Ks (glossy) or Kr (mirror) -- colours stand in for n and k.
#pragma once

#include <memory>

#include "materials/material.h"

namespace candela {

class MaterialInputs;

class ShinyMetalMaterial : public Material {
 public:
  ShinyMetalMaterial(const Texture<Spectrum>* ks, const Texture<Spectrum>* kr,
                     const Texture<Float>* roughness, const Texture<Float>* bump = nullptr)
      : Material(bump), ks_(ks), kr_(kr), roughness_(roughness) {}
  const BSDF* getBSDF(const SurfaceInteraction& si, MemoryArena& arena) const override;
  bool maybeSpecular() const override { return true; }

 private:
  const Texture<Spectrum>*ks_, *kr_;
  const Texture<Float>* roughness_;
};

// The material of a Material "shinymetal" statement (materials/material_plugins.cpp).
std::unique_ptr<Material> createShinyMetalMaterial(MaterialInputs& in);

}  // namespace candela
