#include "materials/substrate.h"

#include "materials/material_inputs.h"
#include "materials/plastic.h"
#include "reflection/fresnel_blend.h"

namespace candela {

const BSDF* SubstrateMaterial::getBSDF(const SurfaceInteraction& si0, MemoryArena& arena) const {
  BumpedPointStorage bumped;
  const SurfaceInteraction& si = shadingPoint(si0, &bumped);
  BSDF* bsdf = arena.make<BSDF>(si);
  Spectrum kd = clampSpectrum(kd_->evaluate(si)), ks = clampSpectrum(ks_->evaluate(si));
  if (kd.isBlack() && ks.isBlack()) return bsdf;
  if (trowbridgeReitz_) {
    bsdf->add(
        arena.make<TrowbridgeReitzFresnelBlend>(kd, ks, trowbridgeReitz_->distribution(si, arena)));
    return bsdf;
  }
  const MicrofacetDistribution* d = arena.make<AnisotropicDistribution>(
      blinnExponent(uRoughness_->evaluate(si)), blinnExponent(vRoughness_->evaluate(si)));
  bsdf->add(arena.make<FresnelBlend>(kd, ks, d));
  return bsdf;
}

std::unique_ptr<Material> createSubstrateMaterial(MaterialInputs& in) {
  const Texture<Float>* bump = in.bumpMap();
  if (in.pbrtV3Models()) {
    TrowbridgeReitzRoughness r;
    r.remap = in.params().getOneBool("remaproughness", true);
    r.u = in.scalar("uroughness", 0.1f);
    r.v = in.scalar("vroughness", 0.1f);
    return std::make_unique<SubstrateMaterial>(in.spectrum("Kd", Spectrum(0.5f)),
                                               in.spectrum("Ks", Spectrum(0.5f)), r, bump);
  }
  return std::make_unique<SubstrateMaterial>(
      in.spectrum("Kd", Spectrum(0.5f)), in.spectrum("Ks", Spectrum(0.5f)),
      in.scalar("uroughness", 0.1f), in.scalar("vroughness", 0.1f), bump);
}

}  // namespace candela
