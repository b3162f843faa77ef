// "plastic" (lrt draft §10.3; pbrt-v2 defaults Kd .25, Ks .25, roughness .1): a diffuse base
// under a glossy Blinn coat, exponent 1 / roughness. The coat's Fresnel term is air (1) outside
// and index 1.5 inside. The seeds print FresnelDielectric(1.5, 1), which puts the index outside
// and makes the coat a total reflector past 41.8 degrees -- a known defect of the book code
// (pbrt-v3 issue #210), not copied here.
#pragma once

#include "materials/material.h"

namespace candela {

class PlasticMaterial : public Material {
 public:
  PlasticMaterial(const Texture<Spectrum>* kd, const Texture<Spectrum>* ks,
                  const Texture<Float>* roughness, const Texture<Float>* bump = nullptr)
      : Material(bump), kd_(kd), ks_(ks), roughness_(roughness) {}
  const BSDF* getBSDF(const SurfaceInteraction& si, MemoryArena& arena) const override;

 private:
  const Texture<Spectrum>*kd_, *ks_;
  const Texture<Float>* roughness_;
};

// Blinn exponent 1 / roughness, with roughness kept away from 0 (an infinite exponent).
Float blinnExponent(Float roughness);

}  // namespace candela
