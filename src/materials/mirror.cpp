#include "materials/mirror.h"

#include "materials/material_inputs.h"
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

std::unique_ptr<Material> createMirrorMaterial(MaterialInputs& in) {
  return std::make_unique<MirrorMaterial>(in.spectrum("Kr", Spectrum(0.9f)), in.bumpMap());
}

}  // namespace candela
