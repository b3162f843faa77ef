#include "assembly/hair_material_params.h"

#include "assembly/constant_values.h"
#include "materials/hair.h"

namespace candela {

namespace {

// Whether the statement carries the parameter, without counting as a use of it.
bool written(const MaterialDesc& d, const std::string& name) {
  for (const ParamItem& item : d.params.items())
    if (item.name == name) return true;
  return false;
}

}  // namespace

std::unique_ptr<Material> createHairMaterial(const MaterialDesc& d, TextureFactory& textures) {
  auto scalar = [&](const char* name, Float def) { return textures.scalar(d, name, def); };
  HairAbsorption a;
  if (written(d, "sigma_a")) {
    requireConstantValues(d.params, "sigma_a", ValueRange::nonNegative());
    a.sigmaA = textures.spectrum(d, "sigma_a", Spectrum(0));
  } else if (written(d, "color")) {
    requireConstantValues(d.params, "color", ValueRange::within(0, 1));
    a.color = textures.spectrum(d, "color", Spectrum(0));
  } else if (written(d, "eumelanin") || written(d, "pheomelanin")) {
    requireConstantValues(d.params, "eumelanin", ValueRange::nonNegative());
    requireConstantValues(d.params, "pheomelanin", ValueRange::nonNegative());
    a.eumelanin = scalar("eumelanin", 0);
    a.pheomelanin = scalar("pheomelanin", 0);
  } else {
    // Brown hair (pbrt-v3's default).
    a.eumelanin = scalar("eumelanin", 1.3f);
  }
  requireConstantValues(d.params, "eta", ValueRange::atLeast(1));
  requireConstantValues(d.params, "eta", ValueRange::finite());
  requireConstantValues(d.params, "beta_m", ValueRange::aboveUpTo(0, 1));
  requireConstantValues(d.params, "beta_n", ValueRange::aboveUpTo(0, 1));
  requireConstantValues(d.params, "alpha", ValueRange::finite());
  return std::make_unique<HairMaterial>(a, scalar("eta", 1.55f), scalar("beta_m", 0.3f),
                                        scalar("beta_n", 0.3f), scalar("alpha", 2));
}

}  // namespace candela
