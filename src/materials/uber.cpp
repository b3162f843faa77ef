#include "materials/uber.h"

#include "materials/material_inputs.h"
#include "materials/plastic.h"
#include "reflection/microfacet.h"
#include "reflection/specular.h"
#include "reflection/trowbridge_reitz_bxdfs.h"

namespace candela {

const BSDF* UberMaterial::getBSDF(const SurfaceInteraction& si0, MemoryArena& arena) const {
  BumpedPointStorage bumped;
  const SurfaceInteraction& si = shadingPoint(si0, &bumped);
  Spectrum op = clampSpectrum(t_.opacity->evaluate(si), 0, 1);
  Float eta = t_.index->evaluate(si);
  bool opaque = op == Spectrum(1);
  BSDF* bsdf = arena.make<BSDF>(si, trowbridgeReitz_ && opaque ? eta : Float(1));
  if (!opaque) bsdf->add(arena.make<SpecularTransmission>(Spectrum(1) - op, Float(1), Float(1)));
  Spectrum kd = op * clampSpectrum(t_.kd->evaluate(si));
  if (!kd.isBlack()) bsdf->add(arena.make<LambertianReflection>(kd));
  Spectrum ks = op * clampSpectrum(t_.ks->evaluate(si));
  if (!ks.isBlack()) {
    const Fresnel* fresnel = arena.make<FresnelDielectric>(Float(1), eta);
    if (trowbridgeReitz_) {
      bsdf->add(arena.make<TrowbridgeReitzReflection>(ks, fresnel,
                                                      trowbridgeReitz_->distribution(si, arena)));
    } else {
      const MicrofacetDistribution* d =
          arena.make<BlinnDistribution>(blinnExponent(t_.roughness->evaluate(si)));
      bsdf->add(arena.make<MicrofacetReflection>(ks, fresnel, d));
    }
  }
  Spectrum kr = op * clampSpectrum(t_.kr->evaluate(si));
  if (!kr.isBlack())
    bsdf->add(arena.make<SpecularReflection>(kr, arena.make<FresnelDielectric>(Float(1), eta)));
  if (t_.kt) {
    Spectrum kt = op * clampSpectrum(t_.kt->evaluate(si));
    if (!kt.isBlack()) bsdf->add(arena.make<SpecularTransmission>(kt, Float(1), eta));
  }
  return bsdf;
}

bool UberMaterial::maybeSpecular() const {
  auto constantBlack = [](const Texture<Spectrum>* t) {
    if (!t) return true;
    const auto* c = dynamic_cast<const ConstantTexture<Spectrum>*>(t);
    return c && clampSpectrum(c->value()).isBlack();
  };
  const auto* opacity = dynamic_cast<const ConstantTexture<Spectrum>*>(t_.opacity);
  bool opaque = opacity && clampSpectrum(opacity->value(), 0, 1) == Spectrum(1);
  return !(constantBlack(t_.kr) && constantBlack(t_.kt) && opaque);
}

std::unique_ptr<Material> createUberMaterial(MaterialInputs& in) {
  const Texture<Float>* bump = in.bumpMap();
  if (in.pbrtV3Models()) {
    TrowbridgeReitzRoughness r;
    r.remap = in.params().getOneBool("remaproughness", true);
    // v falls back to u here, to roughness in metal: pbrt-v3 differs between the two.
    r.u = in.params().find("uroughness") ? in.scalar("uroughness", 0) : nullptr;
    if (!r.u) r.u = in.scalar("roughness", 0.1f);
    r.v = in.params().find("vroughness") ? in.scalar("vroughness", 0) : nullptr;
    if (!r.v) r.v = r.u;
    const Texture<Float>* index =
        in.params().find("eta") ? in.scalar("eta", 1.5f) : in.scalar("index", 1.5f);
    UberMaterial::Textures t{in.spectrum("Kd", Spectrum(0.25f)),
                             in.spectrum("Ks", Spectrum(0.25f)),
                             in.spectrum("Kr", Spectrum(0)),
                             in.spectrum("opacity", Spectrum(1)),
                             nullptr,
                             index,
                             in.spectrum("Kt", Spectrum(0))};
    return std::make_unique<UberMaterial>(t, r, bump);
  }
  return std::make_unique<UberMaterial>(
      UberMaterial::Textures{in.spectrum("Kd", Spectrum(0.25f)), in.spectrum("Ks", Spectrum(0.25f)),
                             in.spectrum("Kr", Spectrum(0)), in.spectrum("opacity", Spectrum(1)),
                             in.scalar("roughness", 0.1f), in.scalar("index", 1.5f)},
      bump);
}

}  // namespace candela
