#include "materials/glass.h"

#include "reflection/specular.h"
#include "reflection/trowbridge_reitz_bxdfs.h"
#include "reflection/trowbridge_reitz_dielectric.h"

namespace candela {

const BSDF* GlassMaterial::getBSDF(const SurfaceInteraction& si0, MemoryArena& arena) const {
  BumpedPointStorage bumped;
  const SurfaceInteraction& si = shadingPoint(si0, &bumped);
  Float eta = index_->evaluate(si);
  BSDF* bsdf = arena.make<BSDF>(si, eta);
  Spectrum r = clampSpectrum(kr_->evaluate(si)), t = clampSpectrum(kt_->evaluate(si));
  if (trowbridgeReitz_ && !trowbridgeReitz_->smoothAt(si)) {
    const TrowbridgeReitzDistribution* d = trowbridgeReitz_->distribution(si, arena);
    // Both lobes: one BxDF that reflects or refracts by the Fresnel term of the microfacet it
    // draws (pbrt 4e §9.7), rather than pbrt-v3's two chosen half and half: the same value,
    // a fraction of the variance.
    if (!r.isBlack() && !t.isBlack()) {
      bsdf->add(arena.make<TrowbridgeReitzDielectric>(r, t, d, Float(1), eta));
      return bsdf;
    }
    if (!r.isBlack())
      bsdf->add(arena.make<TrowbridgeReitzReflection>(
          r, arena.make<FresnelDielectric>(Float(1), eta), d));
    if (!t.isBlack()) bsdf->add(arena.make<TrowbridgeReitzTransmission>(t, d, Float(1), eta));
    return bsdf;
  }
  if (!r.isBlack())
    bsdf->add(arena.make<SpecularReflection>(r, arena.make<FresnelDielectric>(Float(1), eta)));
  if (!t.isBlack()) bsdf->add(arena.make<SpecularTransmission>(t, Float(1), eta));
  return bsdf;
}

}  // namespace candela
