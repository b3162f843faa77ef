#include "materials/plastic.h"

#include "reflection/microfacet.h"

namespace candela {

Float blinnExponent(Float roughness) { return 1 / std::max(roughness, Float(1e-5)); }

const BSDF* PlasticMaterial::getBSDF(const SurfaceInteraction& si0, MemoryArena& arena) const {
  SurfaceInteraction bumped;
  const SurfaceInteraction& si = shadingPoint(si0, &bumped);
  BSDF* bsdf = arena.make<BSDF>(si);
  Spectrum kd = clampSpectrum(kd_->evaluate(si));
  if (!kd.isBlack()) bsdf->add(arena.make<LambertianReflection>(kd));
  Spectrum ks = clampSpectrum(ks_->evaluate(si));
  if (!ks.isBlack()) {
    const Fresnel* fresnel = arena.make<FresnelDielectric>(Float(1), Float(1.5));
    const MicrofacetDistribution* d =
        arena.make<BlinnDistribution>(blinnExponent(roughness_->evaluate(si)));
    bsdf->add(arena.make<MicrofacetReflection>(ks, fresnel, d));
  }
  return bsdf;
}

}  // namespace candela
