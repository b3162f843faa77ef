// "plastic" (lrt draft §10.3; pbrt-v2 defaults Kd .25, Ks .25, roughness .1): a diffuse base
// under a glossy Blinn coat, exponent 1 / roughness. pbrt-v3's plastic (same defaults,
// remaproughness) puts a Trowbridge-Reitz coat with Smith masking there instead (pbrt 3e §9.2.2).
//
// The coat's Fresnel term is air (1) outside and index 1.5 inside. The book code of both
// versions evaluates FresnelDielectric(1.5, 1), which puts the index outside and makes the coat a
// total reflector past 41.8 degrees -- a known defect (pbrt-v3 issue #210), not copied by
// default; CoatFresnel::ReversedAsPbrt reproduces it for comparisons with pbrt's images.
#pragma once

#include <memory>

#include <optional>

#include "core/compatibility.h"
#include "materials/material.h"
#include "materials/trowbridge_reitz_roughness.h"

namespace candela {

class MaterialInputs;

class PlasticMaterial : public Material {
 public:
  PlasticMaterial(const Texture<Spectrum>* kd, const Texture<Spectrum>* ks,
                  const Texture<Float>* roughness, const Texture<Float>* bump = nullptr,
                  CoatFresnel coat = CoatFresnel::Exact)
      : Material(bump), kd_(kd), ks_(ks), roughness_(roughness), coat_(coat) {}
  // pbrt-v3's model.
  PlasticMaterial(const Texture<Spectrum>* kd, const Texture<Spectrum>* ks,
                  const TrowbridgeReitzRoughness& roughness, const Texture<Float>* bump = nullptr,
                  CoatFresnel coat = CoatFresnel::Exact)
      : Material(bump),
        kd_(kd),
        ks_(ks),
        roughness_(nullptr),
        coat_(coat),
        trowbridgeReitz_(roughness) {}
  const BSDF* getBSDF(const SurfaceInteraction& si, MemoryArena& arena) const override;

 private:
  const Texture<Spectrum>*kd_, *ks_;
  const Texture<Float>* roughness_;  // pbrt-v2's Blinn roughness
  CoatFresnel coat_;
  std::optional<TrowbridgeReitzRoughness> trowbridgeReitz_;
};

// Blinn exponent 1 / roughness, with roughness kept away from 0 (an infinite exponent).
Float blinnExponent(Float roughness);

// The material of a Material "plastic" statement (materials/material_plugins.cpp).
std::unique_ptr<Material> createPlasticMaterial(MaterialInputs& in);

}  // namespace candela
