#include "materials/disney.h"

#include "reflection/brdf_to_btdf.h"
#include "reflection/disney_clearcoat.h"
#include "reflection/disney_diffuse.h"
#include "reflection/disney_fresnel.h"
#include "reflection/thin_sheet_transmission.h"
#include "reflection/trowbridge_reitz_bxdfs.h"

namespace candela {

namespace {

Float unit(const Texture<Float>* t, const SurfaceInteraction& si) {
  return clamp(t->evaluate(si), 0, 1);
}

Spectrum lerp(Float t, const Spectrum& a, const Spectrum& b) { return a * (1 - t) + b * t; }

// Burley 2012 §5.6: anisotropy shortens one axis and lengthens the other, at most 10:1.
const TrowbridgeReitzDistribution* distribution(Float roughness, Float aspect, MemoryArena& arena) {
  Float a = roughness * roughness;
  return arena.make<TrowbridgeReitzDistribution>(std::max(Float(0.001), a / aspect),
                                                 std::max(Float(0.001), a * aspect));
}

}  // namespace

const BSDF* DisneyMaterial::getBSDF(const SurfaceInteraction& si0, MemoryArena& arena) const {
  BumpedPointStorage bumped;
  const SurfaceInteraction& si = shadingPoint(si0, &bumped);
  Spectrum c = clampSpectrum(t_.color->evaluate(si), 0, 1);
  Float metallic = unit(t_.metallic, si), specTrans = unit(t_.specTrans, si);
  Float rough = unit(t_.roughness, si);
  Float eta = t_.eta->evaluate(si);
  if (!(eta > 0)) eta = 1;  // a texture's bad value; constants are checked when parsed
  Float diffuse = (1 - metallic) * (1 - specTrans);
  Float transmission = (1 - metallic) * specTrans;
  Float diffTrans = clamp(t_.diffTrans->evaluate(si), 0, 2) / 2;
  Float lum = c.y();
  Spectrum tint = lum > 0 ? c / lum : Spectrum(1);

  // Only a solid surface's refraction is an interface with an index inside.
  BSDF* bsdf = arena.make<BSDF>(si, !t_.thin && transmission > 0 ? eta : Float(1));
  if (diffuse > 0) {
    Spectrum cd = c * diffuse;
    if (t_.thin) {
      Float flat = unit(t_.flatness, si);
      Spectrum reflected = cd * (1 - diffTrans);
      if (flat < 1) {
        bsdf->add(arena.make<DisneyDiffuse>(reflected * (1 - flat)));
        bsdf->add(arena.make<DisneyRetroReflection>(reflected * (1 - flat), rough));
      }
      if (flat > 0) bsdf->add(arena.make<DisneyFakeSubsurface>(reflected * flat, rough));
      if (diffTrans > 0)
        bsdf->add(arena.make<BRDFToBTDF>(arena.make<LambertianReflection>(cd * diffTrans)));
    } else {
      bsdf->add(arena.make<DisneyDiffuse>(cd));
      bsdf->add(arena.make<DisneyRetroReflection>(cd, rough));
    }
    Float sheen = unit(t_.sheen, si);
    if (sheen > 0)
      bsdf->add(arena.make<DisneySheen>(lerp(unit(t_.sheenTint, si), Spectrum(1), tint) *
                                        (diffuse * sheen)));
  }

  Float aspect = std::sqrt(1 - Float(0.9) * unit(t_.anisotropic, si));
  const TrowbridgeReitzDistribution* d = distribution(rough, aspect, arena);
  Spectrum dielectricR0 =
      lerp(unit(t_.specularTint, si), Spectrum(1), tint) * DisneyFresnel::r0FromEta(eta);
  const Fresnel* fresnel =
      arena.make<DisneyFresnel>(lerp(metallic, dielectricR0, c), metallic, eta, t_.thin);
  bsdf->add(arena.make<TrowbridgeReitzReflection>(Spectrum(1), fresnel, d));

  Float clearcoat = unit(t_.clearcoat, si);
  if (clearcoat > 0) bsdf->add(arena.make<DisneyClearcoat>(clearcoat, unit(t_.clearcoatGloss, si)));

  if (transmission > 0) {
    // Thin sheets refract with a roughness scaled by the index (Burley 2015 §5.2, fig. 15).
    Spectrum t = sqrt(c) * transmission;
    if (t_.thin) {
      const TrowbridgeReitzDistribution* scaled =
          distribution(clamp((Float(0.65) * eta - Float(0.35)) * rough, 0, 1), aspect, arena);
      bsdf->add(arena.make<ThinSheetTransmission>(
          arena.make<TrowbridgeReitzTransmission>(t, scaled, Float(1), eta), eta));
    } else {
      bsdf->add(arena.make<TrowbridgeReitzTransmission>(t, d, Float(1), eta));
    }
  }
  return bsdf;
}

}  // namespace candela
