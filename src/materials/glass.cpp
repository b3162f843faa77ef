#include "materials/glass.h"

#include "reflection/specular.h"
#include "reflection/trowbridge_reitz_bxdfs.h"

namespace candela {

const BSDF* GlassMaterial::getBSDF(const SurfaceInteraction& si0, MemoryArena& arena) const {
  BumpedPointStorage bumped;
  const SurfaceInteraction& si = shadingPoint(si0, &bumped);
  Float eta = index_->evaluate(si);
  BSDF* bsdf = arena.make<BSDF>(si, eta);
  Spectrum r = clampSpectrum(kr_->evaluate(si)), t = clampSpectrum(kt_->evaluate(si));
  if (trowbridgeReitz_ && !trowbridgeReitz_->smoothAt(si)) {
    const TrowbridgeReitzDistribution* d = trowbridgeReitz_->distribution(si, arena);
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
