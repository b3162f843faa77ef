// pbrt-v3's Material "disney" from its statement (see createDisneyMaterial in materials/disney.h).
#include "materials/constant_values.h"
#include "materials/disney.h"
#include "materials/material_inputs.h"
#include "textures/texture.h"

namespace candela {

std::unique_ptr<Material> createDisneyMaterial(MaterialInputs& in) {
  const ParamSet& params = in.params();
  auto unit = [&](const char* name, Float def) {
    requireConstantValues(params, name, ValueRange::within(0, 1));
    return in.scalar(name, def);
  };
  // A colour converted from a spectrum may come out a little above 1: clamped, not an error.
  requireConstantValues(params, "color", ValueRange::atLeast(0));
  requireConstantValues(params, "difftrans", ValueRange::within(0, 2));
  requireConstantValues(params, "scatterdistance", ValueRange::atLeast(0));
  requireConstantValues(params, "eta", ValueRange::positive());
  DisneyMaterial::Textures t;
  t.color = in.spectrum("color", Spectrum(0.5f));
  t.metallic = unit("metallic", 0);
  t.eta = in.scalar("eta", 1.5f);
  t.roughness = unit("roughness", 0.5f);
  t.specularTint = unit("speculartint", 0);
  t.anisotropic = unit("anisotropic", 0);
  t.sheen = unit("sheen", 0);
  t.sheenTint = unit("sheentint", 0.5f);
  t.clearcoat = unit("clearcoat", 0);
  t.clearcoatGloss = unit("clearcoatgloss", 1);
  t.specTrans = unit("spectrans", 0);
  t.flatness = unit("flatness", 0);
  t.diffTrans = in.scalar("difftrans", 1);
  t.thin = params.getOneBool("thin", false);
  // Read even when unused (thin surfaces ignore it, as pbrt-v3 does), so it is not reported as
  // an unknown parameter.
  const Texture<Spectrum>* sd = in.spectrum("scatterdistance", Spectrum(0));
  const auto* constant = dynamic_cast<const ConstantTexture<Spectrum>*>(sd);
  bool maybePositive = !constant || !constant->value().isBlack();
  if (!t.thin && maybePositive)
    in.warn(in.locationOf("scatterdistance"),
            "disney: subsurface scattering (\"scatterdistance\" > 0) is not implemented; the "
            "diffuse lobe approximates it");
  return std::make_unique<DisneyMaterial>(t, in.bumpMap());
}

}  // namespace candela
