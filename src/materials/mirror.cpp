#include "materials/mirror.h"

#include "reflection/specular.h"

namespace candela {

const BSDF* MirrorMaterial::getBSDF(const SurfaceInteraction& si0, MemoryArena& arena) const {
  BumpedPointStorage bumped;
  const SurfaceInteraction& si = shadingPoint(si0, &bumped);
  BSDF* bsdf = arena.make<BSDF>(si);
  Spectrum r = clampSpectrum(kr_->evaluate(si));
  if (!r.isBlack()) bsdf->add(arena.make<SpecularReflection>(r, arena.make<FresnelNoOp>()));
  return bsdf;
}

}  // namespace candela
