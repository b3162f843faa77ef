#include "materials/metal.h"

#include "materials/plastic.h"
#include "reflection/microfacet.h"
#include "reflection/trowbridge_reitz_bxdfs.h"

namespace candela {

const BSDF* MetalMaterial::getBSDF(const SurfaceInteraction& si0, MemoryArena& arena) const {
  BumpedPointStorage bumped;
  const SurfaceInteraction& si = shadingPoint(si0, &bumped);
  BSDF* bsdf = arena.make<BSDF>(si);
  const Fresnel* fresnel = arena.make<FresnelConductor>(eta_->evaluate(si), k_->evaluate(si));
  if (trowbridgeReitz_) {
    bsdf->add(arena.make<TrowbridgeReitzReflection>(Spectrum(1), fresnel,
                                                    trowbridgeReitz_->distribution(si, arena)));
    return bsdf;
  }
  const MicrofacetDistribution* d =
      arena.make<BlinnDistribution>(blinnExponent(roughness_->evaluate(si)));
  bsdf->add(arena.make<MicrofacetReflection>(Spectrum(1), fresnel, d));
  return bsdf;
}

}  // namespace candela
