#include "materials/hair.h"

#include "reflection/hair_absorption.h"
#include "reflection/hair_bxdf.h"

namespace candela {

const BSDF* HairMaterial::getBSDF(const SurfaceInteraction& si, MemoryArena& arena) const {
  Float betaM = clamp(betaM_->evaluate(si), kMinRoughness, 1);
  Float betaN = clamp(betaN_->evaluate(si), kMinRoughness, 1);
  Float eta = std::max(Float(1), eta_->evaluate(si));
  Spectrum sigmaA;
  if (absorption_.sigmaA) {
    sigmaA = clampSpectrum(absorption_.sigmaA->evaluate(si));
  } else if (absorption_.color) {
    sigmaA =
        hair::sigmaAFromReflectance(clampSpectrum(absorption_.color->evaluate(si), 0, 1), betaN);
  } else {
    auto concentration = [&](const Texture<Float>* t) {
      return t ? std::max(Float(0), t->evaluate(si)) : Float(0);
    };
    sigmaA = hair::sigmaAFromConcentration(concentration(absorption_.eumelanin),
                                           concentration(absorption_.pheomelanin));
  }
  Float h = -1 + 2 * clamp(si.uv[1], 0, 1);
  BSDF* bsdf = arena.make<BSDF>(si);
  bsdf->add(arena.make<HairBxDF>(h, eta, sigmaA, betaM, betaN, alpha_->evaluate(si)));
  return bsdf;
}

}  // namespace candela
