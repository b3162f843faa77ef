#include "materials/uber.h"

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

}  // namespace candela
