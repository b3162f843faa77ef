// pbrt-v3's "disney" material: Disney's principled BSDF (Burley 2012, "Physically-Based Shading
// at Disney"; Burley 2015, "Extending the Disney BRDF to a BSDF with Integrated Subsurface
// Scattering"). Parameters are textures in [0, 1] unless stated: color (.5), metallic (0), eta
// (1.5), roughness (.5), speculartint (0), anisotropic (0), sheen (0), sheentint (.5), clearcoat
// (0), clearcoatgloss (1), spectrans (0), scatterdistance (0), flatness (0), difftrans (1, in
// [0, 2]) and the bool thin (false). Values outside their ranges are clamped where evaluated.
//
// With C the colour, its hue C_tint = C / luminance(C), and the weights
//   diffuse = (1 - metallic)(1 - spectrans), transmission = (1 - metallic) spectrans
// (the blends of Burley 2015 §3: metallic over a specTrans mix of diffuse and glass), the lobes
// are:
//   - solid: Burley's diffuse and retro-reflection (Burley 2015 §3), weight diffuse C;
//     thin: the same times (1 - flatness)(1 - difftrans / 2), plus the fake subsurface lobe
//     times flatness (1 - difftrans / 2) (Burley 2015 §5.3), and Lambertian transmission
//     diffuse C difftrans / 2;
//   - sheen: diffuse sheen lerp(sheentint, 1, C_tint);
//   - specular: Trowbridge-Reitz reflection, alpha_x = max(.001, roughness^2 / aspect),
//     alpha_y = max(.001, roughness^2 aspect), aspect = sqrt(1 - .9 anisotropic) (Burley 2012
//     §5.6), Fresnel DisneyFresnel with r0 = lerp(metallic, R0(eta) lerp(speculartint, 1,
//     C_tint), C); two-sided on thin surfaces (no total internal reflection from the back);
//   - clearcoat: DisneyClearcoat(clearcoat, clearcoatgloss) when clearcoat > 0;
//   - specular transmission: rough dielectric refraction into eta with tint transmission
//     sqrt(C) (so that two crossings give C); thin: roughness scaled by (.65 eta - .35)
//     (Burley 2015 §5.2, fig. 15).
// Where pbrt-v3's implementation differs, candela follows the papers' weights to keep the
// albedo bounded: pbrt-v3 weights neither the specular transmission by 1 - metallic nor the thin
// Lambertian transmission by the diffuse weight, and adds thin surfaces' retro-reflection at full
// weight whatever flatness and difftrans, and gives thin surfaces' backs total internal
// reflection. Thin surfaces refract in the directions pbrt-v3's do (one rough interface into
// eta) without its change of radiance (ThinSheetTransmission): the sheet has air on both sides.
// Subsurface scattering (scatterdistance > 0 on a solid surface: pbrt-v3 replaces the diffuse lobe
// with a BSSRDF) is not implemented: the diffuse lobe stays, its far-field approximation (the scene
// factory warns).
#pragma once

#include <memory>

#include "materials/material.h"

namespace candela {

class MaterialInputs;

class DisneyMaterial : public Material {
 public:
  struct Textures {
    const Texture<Spectrum>* color;
    const Texture<Float>*metallic, *eta, *roughness, *specularTint, *anisotropic, *sheen,
        *sheenTint, *clearcoat, *clearcoatGloss, *specTrans, *flatness, *diffTrans;
    bool thin = false;
  };
  explicit DisneyMaterial(const Textures& t, const Texture<Float>* bump = nullptr)
      : Material(bump), t_(t) {}
  const BSDF* getBSDF(const SurfaceInteraction& si, MemoryArena& arena) const override;

 private:
  Textures t_;
};

// The material of a Material "disney" statement (materials/disney_params.cpp). Constant values
// outside their ranges are located errors: eta must be positive, difftrans in [0, 2], color and
// scatterdistance non-negative, the others in [0, 1]; a scatterdistance that may be positive on
// a solid surface is warned about (no subsurface scattering), once, at the parameter.
std::unique_ptr<Material> createDisneyMaterial(MaterialInputs& in);

}  // namespace candela
