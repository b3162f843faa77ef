// pbrt-v3's "hair" (Chiang et al. 2016; pbrt 4e §9.9): one HairBxDF whose offset across the fibre
// is h = -1 + 2 v from the surface's (u, v), v clamped to [0, 1]. The model needs a shape whose u
// runs along the fibre and v across its width, as pbrt's curve shape parameterises it; on other
// shapes it shades them as if each were a fibre along dp/du. The absorption comes from exactly one
// of sigma_a, color (Chiang et al.'s inversion with beta_n) or the melanin concentrations.
#pragma once

#include <memory>

#include "materials/material.h"

namespace candela {

class MaterialInputs;

// How the fibre's absorption coefficient is given: the first non-null of sigmaA, color, then the
// melanins (a null concentration is 0).
struct HairAbsorption {
  const Texture<Spectrum>* sigmaA = nullptr;
  const Texture<Spectrum>* color = nullptr;
  const Texture<Float>* eumelanin = nullptr;
  const Texture<Float>* pheomelanin = nullptr;
};

class HairMaterial : public Material {
 public:
  HairMaterial(const HairAbsorption& absorption, const Texture<Float>* eta,
               const Texture<Float>* betaM, const Texture<Float>* betaN,
               const Texture<Float>* alpha)
      : absorption_(absorption), eta_(eta), betaM_(betaM), betaN_(betaN), alpha_(alpha) {}
  const BSDF* getBSDF(const SurfaceInteraction& si, MemoryArena& arena) const override;

  // Texture values outside the model's domain are clamped: roughness to [kMinRoughness, 1], eta to
  // at least 1, colour to [0, 1], sigma_a and concentrations to at least 0.
  static constexpr Float kMinRoughness = 1e-3f;

 private:
  HairAbsorption absorption_;
  const Texture<Float>*eta_, *betaM_, *betaN_, *alpha_;
};

// The material of a Material "hair" statement (materials/hair_params.cpp; pbrt-v3's parameters
// and defaults): sigma_a, or color (turned into sigma_a by Chiang et al.'s inversion with beta_n),
// or eumelanin and pheomelanin (a missing one is 0); eumelanin 1.3 when none is given; eta 1.55,
// beta_m .3, beta_n .3, alpha 2 degrees. The first of sigma_a, color and the melanins given wins;
// the others are not read, so reported as unused. Constant values outside the model's domain are
// located errors. The material takes no bump map (pbrt-v3's does not).
std::unique_ptr<Material> createHairMaterial(MaterialInputs& in);

}  // namespace candela
