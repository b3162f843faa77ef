#include "materials/uber.h"

#include "materials/plastic.h"
#include "reflection/microfacet.h"
#include "reflection/specular.h"

namespace candela {

const BSDF* UberMaterial::getBSDF(const SurfaceInteraction& si0, MemoryArena& arena) const {
  SurfaceInteraction bumped;
  const SurfaceInteraction& si = shadingPoint(si0, &bumped);
  BSDF* bsdf = arena.make<BSDF>(si);
  Spectrum op = clampSpectrum(t_.opacity->evaluate(si), 0, 1);
  if (op != Spectrum(1))
    bsdf->add(arena.make<SpecularTransmission>(Spectrum(1) - op, Float(1), Float(1)));
  Float eta = t_.index->evaluate(si);
  Spectrum kd = op * clampSpectrum(t_.kd->evaluate(si));
  if (!kd.isBlack()) bsdf->add(arena.make<LambertianReflection>(kd));
  Spectrum ks = op * clampSpectrum(t_.ks->evaluate(si));
  if (!ks.isBlack()) {
    const MicrofacetDistribution* d =
        arena.make<BlinnDistribution>(blinnExponent(t_.roughness->evaluate(si)));
    bsdf->add(
        arena.make<MicrofacetReflection>(ks, arena.make<FresnelDielectric>(Float(1), eta), d));
  }
  Spectrum kr = op * clampSpectrum(t_.kr->evaluate(si));
  if (!kr.isBlack())
    bsdf->add(arena.make<SpecularReflection>(kr, arena.make<FresnelDielectric>(Float(1), eta)));
  return bsdf;
}

bool UberMaterial::maybeSpecular() const {
  const auto* kr = dynamic_cast<const ConstantTexture<Spectrum>*>(t_.kr);
  const auto* opacity = dynamic_cast<const ConstantTexture<Spectrum>*>(t_.opacity);
  bool noMirror = kr && clampSpectrum(kr->value()).isBlack();
  bool opaque = opacity && clampSpectrum(opacity->value(), 0, 1) == Spectrum(1);
  return !(noMirror && opaque);
}

}  // namespace candela
