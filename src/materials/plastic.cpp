#include "materials/plastic.h"

#include "materials/material_inputs.h"
#include "reflection/microfacet.h"
#include "reflection/trowbridge_reitz_bxdfs.h"

namespace candela {

Float blinnExponent(Float roughness) { return 1 / std::max(roughness, Float(1e-5)); }

const BSDF* PlasticMaterial::getBSDF(const SurfaceInteraction& si0, MemoryArena& arena) const {
  BumpedPointStorage bumped;
  const SurfaceInteraction& si = shadingPoint(si0, &bumped);
  BSDF* bsdf = arena.make<BSDF>(si);
  Spectrum kd = clampSpectrum(kd_->evaluate(si));
  if (!kd.isBlack()) bsdf->add(arena.make<LambertianReflection>(kd));
  Spectrum ks = clampSpectrum(ks_->evaluate(si));
  if (!ks.isBlack()) {
    const Fresnel* fresnel = coat_ == CoatFresnel::Exact
                                 ? arena.make<FresnelDielectric>(Float(1), Float(1.5))
                                 : arena.make<FresnelDielectric>(Float(1.5), Float(1));
    if (trowbridgeReitz_) {
      bsdf->add(arena.make<TrowbridgeReitzReflection>(ks, fresnel,
                                                      trowbridgeReitz_->distribution(si, arena)));
    } else {
      const MicrofacetDistribution* d =
          arena.make<BlinnDistribution>(blinnExponent(roughness_->evaluate(si)));
      bsdf->add(arena.make<MicrofacetReflection>(ks, fresnel, d));
    }
  }
  return bsdf;
}

std::unique_ptr<Material> createPlasticMaterial(MaterialInputs& in) {
  const Texture<Float>* bump = in.bumpMap();
  if (in.pbrtV3Models()) {
    TrowbridgeReitzRoughness r;
    r.remap = in.params().getOneBool("remaproughness", true);
    r.u = r.v = in.scalar("roughness", 0.1f);
    return std::make_unique<PlasticMaterial>(in.spectrum("Kd", Spectrum(0.25f)),
                                             in.spectrum("Ks", Spectrum(0.25f)), r, bump,
                                             in.plasticCoat());
  }
  return std::make_unique<PlasticMaterial>(in.spectrum("Kd", Spectrum(0.25f)),
                                           in.spectrum("Ks", Spectrum(0.25f)),
                                           in.scalar("roughness", 0.1f), bump, in.plasticCoat());
}

}  // namespace candela
