#include "assembly/hair_material_params.h"

#include <cmath>
#include <limits>

#include "materials/hair.h"

namespace candela {

namespace {

// Whether the statement carries the parameter, without counting as a use of it.
bool written(const MaterialDesc& d, const std::string& name) {
  for (const ParamItem& item : d.params.items())
    if (item.name == name) return true;
  return false;
}

// A constant (not a texture reference) must have every value in [lo, hi], or (lo, hi] when
// lowOpen.
void requireRange(const MaterialDesc& d, const std::string& name, Float lo, Float hi, bool lowOpen,
                  const std::string& what) {
  const ParamItem* item = d.params.find(name);
  if (!item || item->type == ParamType::Texture) return;
  for (Float v : item->floats)
    if (!(std::isfinite(v) && (lowOpen ? v > lo : v >= lo) && v <= hi))
      throw SceneError(
          item->loc, "hair: \"" + name + "\" must be " + what + " (got " + std::to_string(v) + ")");
}

}  // namespace

std::unique_ptr<Material> createHairMaterial(const MaterialDesc& d, TextureFactory& textures) {
  constexpr Float kInf = std::numeric_limits<Float>::infinity();
  auto scalar = [&](const char* name, Float def) { return textures.scalar(d, name, def); };
  HairAbsorption a;
  if (written(d, "sigma_a")) {
    requireRange(d, "sigma_a", 0, kInf, false, "non-negative and finite in every channel");
    a.sigmaA = textures.spectrum(d, "sigma_a", Spectrum(0));
  } else if (written(d, "color")) {
    requireRange(d, "color", 0, 1, false, "in [0, 1] in every channel");
    a.color = textures.spectrum(d, "color", Spectrum(0));
  } else if (written(d, "eumelanin") || written(d, "pheomelanin")) {
    requireRange(d, "eumelanin", 0, kInf, false, "non-negative and finite");
    requireRange(d, "pheomelanin", 0, kInf, false, "non-negative and finite");
    a.eumelanin = scalar("eumelanin", 0);
    a.pheomelanin = scalar("pheomelanin", 0);
  } else {
    // Brown hair (pbrt-v3's default).
    a.eumelanin = scalar("eumelanin", 1.3f);
  }
  requireRange(d, "eta", 1, kInf, false, "at least 1 and finite");
  requireRange(d, "beta_m", 0, 1, true, "in (0, 1]");
  requireRange(d, "beta_n", 0, 1, true, "in (0, 1]");
  requireRange(d, "alpha", -kInf, kInf, false, "finite");
  return std::make_unique<HairMaterial>(a, scalar("eta", 1.55f), scalar("beta_m", 0.3f),
                                        scalar("beta_n", 0.3f), scalar("alpha", 2));
}

}  // namespace candela
