#include "materials/lafortune_material.h"

#include "materials/material_inputs.h"

namespace candela {

const BSDF* LafortuneMaterial::getBSDF(const SurfaceInteraction& si0, MemoryArena& arena) const {
  BumpedPointStorage bumped;
  const SurfaceInteraction& si = shadingPoint(si0, &bumped);
  BSDF* bsdf = arena.make<BSDF>(si);
  // The draft declares its fits REFLECTION | DIFFUSE (lrt draft §10.9).
  bsdf->add(arena.make<Lafortune>(fit_.diffuse, fit_.lobes, BxDFType(kReflection | kDiffuse)));
  return bsdf;
}

std::unique_ptr<Material> createClayMaterial(MaterialInputs& in) {
  return std::make_unique<LafortuneMaterial>(*lafortuneFit("clay"), in.bumpMap());
}

bool isUnprintedLafortuneFit(std::string_view name) {
  // Named in the draft (§10.9) without coefficients.
  for (std::string_view n : {"felt", "primer", "skin", "bluepaint", "brushedmetal"})
    if (n == name) return true;
  return false;
}

}  // namespace candela
