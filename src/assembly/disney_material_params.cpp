#include "assembly/disney_material_params.h"

#include "assembly/constant_values.h"
#include "materials/disney.h"
#include "textures/texture.h"

namespace candela {

std::unique_ptr<Material> createDisneyMaterial(
    const MaterialDesc& d, TextureFactory& textures, const Texture<Float>* bump,
    const std::function<void(const FileLoc&, const std::string&)>& warn) {
  auto unit = [&](const char* name, Float def) {
    requireConstantValues(d.params, name, ValueRange::within(0, 1));
    return textures.scalar(d, name, def);
  };
  // A colour converted from a spectrum may come out a little above 1: clamped, not an error.
  requireConstantValues(d.params, "color", ValueRange::atLeast(0));
  requireConstantValues(d.params, "difftrans", ValueRange::within(0, 2));
  requireConstantValues(d.params, "scatterdistance", ValueRange::atLeast(0));
  requireConstantValues(d.params, "eta", ValueRange::positive());
  DisneyMaterial::Textures t;
  t.color = textures.spectrum(d, "color", Spectrum(0.5f));
  t.metallic = unit("metallic", 0);
  t.eta = textures.scalar(d, "eta", 1.5f);
  t.roughness = unit("roughness", 0.5f);
  t.specularTint = unit("speculartint", 0);
  t.anisotropic = unit("anisotropic", 0);
  t.sheen = unit("sheen", 0);
  t.sheenTint = unit("sheentint", 0.5f);
  t.clearcoat = unit("clearcoat", 0);
  t.clearcoatGloss = unit("clearcoatgloss", 1);
  t.specTrans = unit("spectrans", 0);
  t.flatness = unit("flatness", 0);
  t.diffTrans = textures.scalar(d, "difftrans", 1);
  t.thin = d.params.getOneBool("thin", false);
  // Read even when unused (thin surfaces ignore it, as pbrt-v3 does), so it is not reported as
  // an unknown parameter.
  const Texture<Spectrum>* sd = textures.spectrum(d, "scatterdistance", Spectrum(0));
  const auto* constant = dynamic_cast<const ConstantTexture<Spectrum>*>(sd);
  bool maybePositive = !constant || !constant->value().isBlack();
  if (!t.thin && maybePositive && warn)
    warn(d.params.locationOf("scatterdistance", d.loc),
         "disney: subsurface scattering (\"scatterdistance\" > 0) is not implemented; the "
         "diffuse lobe approximates it");
  return std::make_unique<DisneyMaterial>(t, bump);
}

}  // namespace candela
