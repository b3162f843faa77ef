#include "materials/lafortune_material.h"

namespace candela {

const BSDF* LafortuneMaterial::getBSDF(const SurfaceInteraction& si0, MemoryArena& arena) const {
  BumpedPointStorage bumped;
  const SurfaceInteraction& si = shadingPoint(si0, &bumped);
  BSDF* bsdf = arena.make<BSDF>(si);
  // The draft declares its fits REFLECTION | DIFFUSE (lrt draft §10.9).
  bsdf->add(arena.make<Lafortune>(fit_.diffuse, fit_.lobes, BxDFType(kReflection | kDiffuse)));
  return bsdf;
}

}  // namespace candela
