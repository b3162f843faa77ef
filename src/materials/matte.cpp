#include "materials/matte.h"

#include "materials/material_inputs.h"

namespace candela {

namespace {
Spectrum reflectance(const Spectrum& kd) { return clampSpectrum(kd, 0, kInfinity); }
Float slopeDeviation(Float sigma) { return clamp(sigma, 0, 90); }
}  // namespace

const BSDF* MatteMaterial::constantBSDF(const SurfaceInteraction& si, MemoryArena& arena) const {
  if (constantLambertian_) return arena.make<BSDF>(si, constantLambertian_.get());
  BSDF* bsdf = arena.make<BSDF>(si);
  if (constantOrenNayar_) bsdf->add(constantOrenNayar_.get());
  return bsdf;
}

MatteMaterial::MatteMaterial(const Texture<Spectrum>* kd, const Texture<Float>* sigma,
                             const Texture<Float>* bump)
    : Material(bump), kd_(kd), sigma_(sigma) {
  auto* kdConstant = dynamic_cast<const ConstantTexture<Spectrum>*>(kd);
  auto* sigmaConstant = dynamic_cast<const ConstantTexture<Float>*>(sigma);
  if (!kdConstant || !sigmaConstant) return;
  constant_ = true;
  Spectrum r = reflectance(kdConstant->value());
  Float s = slopeDeviation(sigmaConstant->value());
  if (r.isBlack()) return;
  if (s == 0)
    constantLambertian_ = std::make_unique<const LambertianReflection>(r);
  else
    constantOrenNayar_ = std::make_unique<const OrenNayar>(r, s);
}

const BSDF* MatteMaterial::getBSDF(const SurfaceInteraction& si, MemoryArena& arena) const {
  return constant_ && !bumpMap() ? constantBSDF(si, arena) : bumpedOrTexturedBSDF(si, arena);
}

const BSDF* MatteMaterial::bumpedOrTexturedBSDF(const SurfaceInteraction& si0,
                                                MemoryArena& arena) const {
  BumpedPointStorage bumped;
  const SurfaceInteraction& si = shadingPoint(si0, &bumped);
  if (constant_) return constantBSDF(si, arena);
  Spectrum r = reflectance(kd_->evaluate(si));
  Float sigma = slopeDeviation(sigma_->evaluate(si));
  // A lone Lambertian in the same frame as constantBSDF's, so that both give the same samples.
  if (!r.isBlack() && sigma == 0) return arena.make<BSDF>(si, arena.make<LambertianReflection>(r));
  BSDF* bsdf = arena.make<BSDF>(si);
  if (!r.isBlack()) bsdf->add(arena.make<OrenNayar>(r, sigma));
  return bsdf;
}

// Kd .5, sigma 0 (Oren-Nayar roughness in degrees; 0 is Lambertian).
std::unique_ptr<Material> createMatteMaterial(MaterialInputs& in) {
  return std::make_unique<MatteMaterial>(in.spectrum("Kd", Spectrum(0.5f)), in.scalar("sigma", 0),
                                         in.bumpMap());
}

}  // namespace candela
