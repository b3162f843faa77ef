#include "materials/mix.h"

#include "materials/material_inputs.h"
#include "materials/scaled_bxdf.h"

namespace candela {

const BSDF* MixMaterial::getBSDF(const SurfaceInteraction& si, MemoryArena& arena) const {
  Spectrum s1 = clampSpectrum(amount_->evaluate(si), 0, 1);
  Spectrum s2 = clampSpectrum(Spectrum(1) - s1, 0, 1);
  const BSDF* b1 = m1_->getBSDF(si, arena);
  const BSDF* b2 = m2_->getBSDF(si, arena);
  BSDF* bsdf = arena.make<BSDF>(si, b1->eta);
  // A weight of 0 drops the component, so that amount 0 or 1 is exactly one material.
  auto addScaled = [&](const BSDF* b, const Spectrum& s) {
    if (s.isBlack()) return;
    for (int i = 0; i < b->numComponents(); ++i)
      bsdf->add(s == Spectrum(1) ? b->component(i) : arena.make<ScaledBxDF>(b->component(i), s));
  };
  addScaled(b1, s1);
  addScaled(b2, s2);
  return bsdf;
}

std::unique_ptr<Material> createMixMaterial(MaterialInputs& in) {
  const Material* m1 = in.namedMaterial("namedmaterial1");
  const Material* m2 = in.namedMaterial("namedmaterial2");
  return std::make_unique<MixMaterial>(m1, m2, in.spectrum("amount", Spectrum(0.5f)));
}

}  // namespace candela
