#include "materials/substrate.h"

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

}  // namespace candela
