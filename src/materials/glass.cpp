#include "materials/glass.h"

#include "materials/material_inputs.h"
#include "reflection/specular.h"
#include "reflection/trowbridge_reitz_bxdfs.h"
#include "reflection/trowbridge_reitz_dielectric.h"

namespace candela {

const BSDF* GlassMaterial::getBSDF(const SurfaceInteraction& si0, MemoryArena& arena) const {
  BumpedPointStorage bumped;
  const SurfaceInteraction& si = shadingPoint(si0, &bumped);
  Float eta = index_->evaluate(si);
  BSDF* bsdf = arena.make<BSDF>(si, eta);
  Spectrum r = clampSpectrum(kr_->evaluate(si)), t = clampSpectrum(kt_->evaluate(si));
  if (trowbridgeReitz_ && !trowbridgeReitz_->smoothAt(si)) {
    const TrowbridgeReitzDistribution* d = trowbridgeReitz_->distribution(si, arena);
    // Both lobes: one BxDF that reflects or refracts by the Fresnel term of the microfacet it
    // draws (pbrt 4e §9.7), rather than pbrt-v3's two chosen half and half: the same value,
    // a fraction of the variance.
    if (!r.isBlack() && !t.isBlack()) {
      bsdf->add(arena.make<TrowbridgeReitzDielectric>(r, t, d, Float(1), eta));
      return bsdf;
    }
    if (!r.isBlack())
      bsdf->add(arena.make<TrowbridgeReitzReflection>(
          r, arena.make<FresnelDielectric>(Float(1), eta), d));
    if (!t.isBlack()) bsdf->add(arena.make<TrowbridgeReitzTransmission>(t, d, Float(1), eta));
    return bsdf;
  }
  if (!r.isBlack())
    bsdf->add(arena.make<SpecularReflection>(r, arena.make<FresnelDielectric>(Float(1), eta)));
  if (!t.isBlack()) bsdf->add(arena.make<SpecularTransmission>(t, Float(1), eta));
  return bsdf;
}

std::unique_ptr<Material> createGlassMaterial(MaterialInputs& in) {
  const Texture<Float>* bump = in.bumpMap();
  if (in.pbrtV3Models()) {
    TrowbridgeReitzRoughness r;
    r.remap = in.params().getOneBool("remaproughness", true);
    r.u = in.scalar("uroughness", 0);
    r.v = in.scalar("vroughness", 0);
    // pbrt-v3 reads "eta" and, without it, "index".
    const Texture<Float>* index =
        in.params().find("eta") ? in.scalar("eta", 1.5f) : in.scalar("index", 1.5f);
    return std::make_unique<GlassMaterial>(in.spectrum("Kr", Spectrum(1)),
                                           in.spectrum("Kt", Spectrum(1)), index, r, bump);
  }
  return std::make_unique<GlassMaterial>(in.spectrum("Kr", Spectrum(1)),
                                         in.spectrum("Kt", Spectrum(1)), in.scalar("index", 1.5f),
                                         bump);
}

}  // namespace candela
