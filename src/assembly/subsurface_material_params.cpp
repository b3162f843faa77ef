#include "assembly/subsurface_material_params.h"

#include "assembly/constant_values.h"
#include "materials/measured_subsurface.h"
#include "materials/subsurface.h"

namespace candela {

namespace {

// A constant float parameter must be positive and finite.
Float positiveFloat(const MaterialDesc& d, const std::string& name, Float def) {
  return d.params.getOneFloat(name, def, ValueRange::positive(), d.loc);
}

}  // namespace

std::unique_ptr<Material> createSubsurfaceMaterial(const MaterialDesc& d, TextureFactory& textures,
                                                   const Texture<Float>* bump) {
  const ParamSet& p = d.params;
  Float eta = positiveFloat(d, "index", 1.33f);
  const Texture<Spectrum>* kr = textures.spectrum(d, "Kr", Spectrum(1));
  if (d.name == "kdsubsurface") {
    const Texture<Spectrum>* kd = textures.spectrum(d, "Kd", Spectrum(0.5f));
    const ParamItem* mfp = p.find("meanfreepath");
    if (!mfp || mfp->type != ParamType::Texture) positiveFloat(d, "meanfreepath", 1);
    return std::make_unique<KdSubsurfaceMaterial>(kd, textures.scalar(d, "meanfreepath", 1), eta,
                                                  kr, bump);
  }
  // pbrt-v2's defaults are whole milk's coefficients.
  MeasuredSubsurface medium{{2.55f, 3.21f, 3.77f}, {0.0011f, 0.0024f, 0.014f}};
  std::string name = p.getOneString("name", "");
  if (!name.empty()) {
    auto found = measuredSubsurface(name);
    if (!found) {
      std::string known;
      for (const std::string& n : measuredSubsurfaceNames())
        known += (known.empty() ? "" : ", ") + n;
      throw SceneError(p.locationOf("name", d.loc),
                       "subsurface: unknown measured medium '" + name + "' (known: " + known + ")");
    }
    medium = *found;
  }
  requireConstantValues(d.params, "sigma_a", ValueRange::nonNegative());
  requireConstantValues(d.params, "sigma_prime_s", ValueRange::nonNegative());
  Float scale = positiveFloat(d, "scale", 1);
  return std::make_unique<SubsurfaceMaterial>(
      scale, textures.spectrum(d, "sigma_a", medium.sigmaA),
      textures.spectrum(d, "sigma_prime_s", medium.sigmaPrimeS), eta, kr, bump);
}

}  // namespace candela
