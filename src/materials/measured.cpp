#include "materials/measured.h"

namespace candela {

const BSDF* MeasuredMaterial::getBSDF(const SurfaceInteraction& si0, MemoryArena& arena) const {
  BumpedPointStorage bumped;
  const SurfaceInteraction& si = shadingPoint(si0, &bumped);
  BSDF* bsdf = arena.make<BSDF>(si);
  if (merl_)
    bsdf->add(arena.make<MeasuredBRDF>(merl_.get()));
  else
    bsdf->add(arena.make<IrregularMeasuredBRDF>(irregular_.get()));
  return bsdf;
}

}  // namespace candela
