#include "materials/subsurface.h"

#include <algorithm>

#include "reflection/specular.h"

namespace candela {

namespace {

const BSDF* specularBoundary(const SurfaceInteraction& si, const Texture<Spectrum>& kr, Float eta,
                             MemoryArena& arena) {
  BSDF* bsdf = arena.make<BSDF>(si);
  Spectrum r = clampSpectrum(kr.evaluate(si));
  if (!r.isBlack())
    bsdf->add(arena.make<SpecularReflection>(r, arena.make<FresnelDielectric>(1, eta)));
  return bsdf;
}

}  // namespace

const BSDF* SubsurfaceMaterial::getBSDF(const SurfaceInteraction& si0, MemoryArena& arena) const {
  BumpedPointStorage bumped;
  return specularBoundary(shadingPoint(si0, &bumped), *kr_, eta_, arena);
}

BSSRDFCoefficients SubsurfaceMaterial::coefficients(const SurfaceInteraction& si) const {
  return {clampSpectrum(sigmaA_->evaluate(si) * scale_),
          clampSpectrum(sigmaPrimeS_->evaluate(si) * scale_), eta_};
}

const BSDF* KdSubsurfaceMaterial::getBSDF(const SurfaceInteraction& si0, MemoryArena& arena) const {
  BumpedPointStorage bumped;
  return specularBoundary(shadingPoint(si0, &bumped), *kr_, eta_, arena);
}

BSSRDFCoefficients KdSubsurfaceMaterial::coefficients(const SurfaceInteraction& si) const {
  Spectrum kd = clampSpectrum(kd_->evaluate(si), 0, 1);
  // A texture may reach zero; the smallest positive path keeps sigma finite.
  Float mfp = std::max(meanFreePath_->evaluate(si), Float(1e-20));
  return coefficientsFromDiffuse(kd, mfp, eta_);
}

}  // namespace candela
