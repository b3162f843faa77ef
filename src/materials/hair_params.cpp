// pbrt-v3's Material "hair" from its statement (see createHairMaterial in materials/hair.h).
#include "materials/constant_values.h"
#include "materials/hair.h"
#include "materials/material_inputs.h"

namespace candela {

namespace {

// Whether the statement carries the parameter, without counting as a use of it.
bool written(const ParamSet& params, const std::string& name) {
  for (const ParamItem& item : params.items())
    if (item.name == name) return true;
  return false;
}

}  // namespace

std::unique_ptr<Material> createHairMaterial(MaterialInputs& in) {
  const ParamSet& params = in.params();
  auto scalar = [&](const char* name, Float def) { return in.scalar(name, def); };
  HairAbsorption a;
  if (written(params, "sigma_a")) {
    requireConstantValues(params, "sigma_a", ValueRange::nonNegative());
    a.sigmaA = in.spectrum("sigma_a", Spectrum(0));
  } else if (written(params, "color")) {
    requireConstantValues(params, "color", ValueRange::within(0, 1));
    a.color = in.spectrum("color", Spectrum(0));
  } else if (written(params, "eumelanin") || written(params, "pheomelanin")) {
    requireConstantValues(params, "eumelanin", ValueRange::nonNegative());
    requireConstantValues(params, "pheomelanin", ValueRange::nonNegative());
    a.eumelanin = scalar("eumelanin", 0);
    a.pheomelanin = scalar("pheomelanin", 0);
  } else {
    // Brown hair (pbrt-v3's default).
    a.eumelanin = scalar("eumelanin", 1.3f);
  }
  requireConstantValues(params, "eta", ValueRange::atLeast(1));
  requireConstantValues(params, "eta", ValueRange::finite());
  requireConstantValues(params, "beta_m", ValueRange::aboveUpTo(0, 1));
  requireConstantValues(params, "beta_n", ValueRange::aboveUpTo(0, 1));
  requireConstantValues(params, "alpha", ValueRange::finite());
  return std::make_unique<HairMaterial>(a, scalar("eta", 1.55f), scalar("beta_m", 0.3f),
                                        scalar("beta_n", 0.3f), scalar("alpha", 2));
}

}  // namespace candela
