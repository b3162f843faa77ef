#include "materials/matte.h"

#include "reflection/oren_nayar.h"

namespace candela {

const BSDF* MatteMaterial::getBSDF(const SurfaceInteraction& si0, MemoryArena& arena) const {
  BumpedPointStorage bumped;
  const SurfaceInteraction& si = shadingPoint(si0, &bumped);
  BSDF* bsdf = arena.make<BSDF>(si);
  Spectrum r = clampSpectrum(kd_->evaluate(si), 0, kInfinity);
  Float sigma = clamp(sigma_->evaluate(si), 0, 90);
  if (r.isBlack()) return bsdf;
  if (sigma == 0)
    bsdf->add(arena.make<LambertianReflection>(r));
  else
    bsdf->add(arena.make<OrenNayar>(r, sigma));
  return bsdf;
}

}  // namespace candela
