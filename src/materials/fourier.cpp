#include "materials/fourier.h"

#include "reflection/fourier_bxdf.h"

namespace candela {

const BSDF* FourierMaterial::getBSDF(const SurfaceInteraction& si0, MemoryArena& arena) const {
  BumpedPointStorage bumped;
  const SurfaceInteraction& si = shadingPoint(si0, &bumped);
  BSDF* bsdf = arena.make<BSDF>(si);
  bsdf->add(arena.make<FourierBSDF>(table_.get()));
  return bsdf;
}

}  // namespace candela
