// The dipole's translucent materials from their statements (pbrt 2e §16.5; pbrt-v2's parameters
// and defaults): "subsurface" and "kdsubsurface".
#include "materials/constant_values.h"
#include "materials/material_inputs.h"
#include "materials/measured_subsurface.h"
#include "materials/subsurface.h"

namespace candela {

namespace {

// A constant float parameter must be positive and finite.
Float positiveFloat(MaterialInputs& in, const std::string& name, Float def) {
  return in.params().getOneFloat(name, def, ValueRange::positive(), in.location());
}

}  // namespace

std::unique_ptr<Material> createKdSubsurfaceMaterial(MaterialInputs& in) {
  const Texture<Float>* bump = in.bumpMap();
  Float eta = positiveFloat(in, "index", 1.33f);
  const Texture<Spectrum>* kr = in.spectrum("Kr", Spectrum(1));
  const Texture<Spectrum>* kd = in.spectrum("Kd", Spectrum(0.5f));
  const ParamItem* mfp = in.params().find("meanfreepath");
  if (!mfp || mfp->type != ParamType::Texture) positiveFloat(in, "meanfreepath", 1);
  return std::make_unique<KdSubsurfaceMaterial>(kd, in.scalar("meanfreepath", 1), eta, kr, bump);
}

std::unique_ptr<Material> createSubsurfaceMaterial(MaterialInputs& in) {
  const Texture<Float>* bump = in.bumpMap();
  const ParamSet& p = in.params();
  Float eta = positiveFloat(in, "index", 1.33f);
  const Texture<Spectrum>* kr = in.spectrum("Kr", Spectrum(1));
  // pbrt-v2's defaults are whole milk's coefficients.
  MeasuredSubsurface medium{{2.55f, 3.21f, 3.77f}, {0.0011f, 0.0024f, 0.014f}};
  std::string name = p.getOneString("name", "");
  if (!name.empty()) {
    auto found = measuredSubsurface(name);
    if (!found) {
      std::string known;
      for (const std::string& n : measuredSubsurfaceNames())
        known += (known.empty() ? "" : ", ") + n;
      throw SceneError(in.locationOf("name"),
                       "subsurface: unknown measured medium '" + name + "' (known: " + known + ")");
    }
    medium = *found;
  }
  requireConstantValues(p, "sigma_a", ValueRange::nonNegative());
  requireConstantValues(p, "sigma_prime_s", ValueRange::nonNegative());
  Float scale = positiveFloat(in, "scale", 1);
  return std::make_unique<SubsurfaceMaterial>(scale, in.spectrum("sigma_a", medium.sigmaA),
                                              in.spectrum("sigma_prime_s", medium.sigmaPrimeS), eta,
                                              kr, bump);
}

}  // namespace candela
