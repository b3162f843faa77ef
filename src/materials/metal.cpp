#include "materials/metal.h"

#include "materials/material_inputs.h"
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

std::unique_ptr<Material> createMetalMaterial(MaterialInputs& in) {
  const Texture<Float>* bump = in.bumpMap();
  if (in.pbrtV3Models()) {
    TrowbridgeReitzRoughness r;
    r.remap = in.params().getOneBool("remaproughness", true);
    // Without both of "uroughness" and "vroughness", the missing one is "roughness".
    const Texture<Float>* u = in.params().find("uroughness") ? in.scalar("uroughness", 0) : nullptr;
    const Texture<Float>* v = in.params().find("vroughness") ? in.scalar("vroughness", 0) : nullptr;
    const Texture<Float>* rough = !u || !v ? in.scalar("roughness", 0.01f) : nullptr;
    r.u = u ? u : rough;
    r.v = v ? v : rough;
    return std::make_unique<MetalMaterial>(in.spectrum("eta", copper::kEta),
                                           in.spectrum("k", copper::kK), r, bump);
  }
  return std::make_unique<MetalMaterial>(in.spectrum("eta", copper::kEta),
                                         in.spectrum("k", copper::kK),
                                         in.scalar("roughness", 0.01f), bump);
}

}  // namespace candela
