#include "materials/shinymetal.h"

#include "materials/material_inputs.h"
#include "materials/plastic.h"
#include "reflection/microfacet.h"
#include "reflection/specular.h"

namespace candela {

const BSDF* ShinyMetalMaterial::getBSDF(const SurfaceInteraction& si0, MemoryArena& arena) const {
  BumpedPointStorage bumped;
  const SurfaceInteraction& si = shadingPoint(si0, &bumped);
  BSDF* bsdf = arena.make<BSDF>(si);
  Spectrum ks = clampSpectrum(ks_->evaluate(si)), kr = clampSpectrum(kr_->evaluate(si));
  const MicrofacetDistribution* d =
      arena.make<BlinnDistribution>(blinnExponent(roughness_->evaluate(si)));
  const Fresnel* glossy = arena.make<FresnelConductor>(fresnelApproxEta(ks), Spectrum(0));
  const Fresnel* mirror = arena.make<FresnelConductor>(fresnelApproxEta(kr), Spectrum(0));
  bsdf->add(arena.make<MicrofacetReflection>(Spectrum(1), glossy, d));
  bsdf->add(arena.make<SpecularReflection>(Spectrum(1), mirror));
  return bsdf;
}

std::unique_ptr<Material> createShinyMetalMaterial(MaterialInputs& in) {
  return std::make_unique<ShinyMetalMaterial>(in.spectrum("Ks", Spectrum(1)),
                                              in.spectrum("Kr", Spectrum(1)),
                                              in.scalar("roughness", 0.1f), in.bumpMap());
}

}  // namespace candela
