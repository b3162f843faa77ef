#include "materials/translucent.h"

#include "materials/material_inputs.h"
#include "materials/plastic.h"
#include "reflection/brdf_to_btdf.h"
#include "reflection/microfacet.h"
#include "reflection/trowbridge_reitz_bxdfs.h"

namespace candela {

const BSDF* TranslucentMaterial::getBSDF(const SurfaceInteraction& si0, MemoryArena& arena) const {
  BumpedPointStorage bumped;
  const SurfaceInteraction& si = shadingPoint(si0, &bumped);
  BSDF* bsdf = arena.make<BSDF>(si, index_);
  Spectrum r = clampSpectrum(reflect_->evaluate(si)), t = clampSpectrum(transmit_->evaluate(si));
  if (r.isBlack() && t.isBlack()) return bsdf;
  Spectrum kd = clampSpectrum(kd_->evaluate(si));
  if (!kd.isBlack()) {
    if (!r.isBlack()) bsdf->add(arena.make<LambertianReflection>(r * kd));
    if (!t.isBlack()) bsdf->add(arena.make<BRDFToBTDF>(arena.make<LambertianReflection>(t * kd)));
  }
  Spectrum ks = clampSpectrum(ks_->evaluate(si));
  if (!ks.isBlack()) {
    const Fresnel* fresnel = arena.make<FresnelDielectric>(Float(1), index_);
    if (trowbridgeReitz_) {
      const TrowbridgeReitzDistribution* d = trowbridgeReitz_->distribution(si, arena);
      if (!r.isBlack()) bsdf->add(arena.make<TrowbridgeReitzReflection>(r * ks, fresnel, d));
      if (!t.isBlack())
        bsdf->add(arena.make<TrowbridgeReitzTransmission>(t * ks, d, Float(1), index_));
      return bsdf;
    }
    const MicrofacetDistribution* d =
        arena.make<BlinnDistribution>(blinnExponent(roughness_->evaluate(si)));
    if (!r.isBlack()) bsdf->add(arena.make<MicrofacetReflection>(r * ks, fresnel, d));
    if (!t.isBlack())
      bsdf->add(arena.make<BRDFToBTDF>(arena.make<MicrofacetReflection>(t * ks, fresnel, d)));
  }
  return bsdf;
}

std::unique_ptr<Material> createTranslucentMaterial(MaterialInputs& in) {
  const Texture<Float>* bump = in.bumpMap();
  if (in.pbrtV3Models()) {
    TrowbridgeReitzRoughness r;
    r.remap = in.params().getOneBool("remaproughness", true);
    r.u = r.v = in.scalar("roughness", 0.1f);
    return std::make_unique<TranslucentMaterial>(
        in.spectrum("Kd", Spectrum(0.25f)), in.spectrum("Ks", Spectrum(0.25f)),
        in.spectrum("reflect", Spectrum(0.5f)), in.spectrum("transmit", Spectrum(0.5f)), r,
        in.params().getOneFloat("index", 1.5f), bump);
  }
  return std::make_unique<TranslucentMaterial>(
      in.spectrum("Kd", Spectrum(0.25f)), in.spectrum("Ks", Spectrum(0.25f)),
      in.spectrum("reflect", Spectrum(0.5f)), in.spectrum("transmit", Spectrum(0.5f)),
      in.scalar("roughness", 0.1f), in.params().getOneFloat("index", 1.5f), bump);
}

}  // namespace candela
