#include "materials/plastic.h"

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

}  // namespace candela
