#include <cmath>
#include <optional>

#include "core/error.h"
#include "fuzz/targets/fuzz_targets.h"
#include "fuzz/targets/lookup_directions.h"
#include "reflection/fourier_bsdf_table.h"
#include "reflection/fourier_bxdf.h"

namespace candela::fuzz {

namespace {

bool finiteDirection(const Vector3f& w) {
  return std::isfinite(w.x) && std::isfinite(w.y) && std::isfinite(w.z);
}

}  // namespace

// A table the reader accepts gives finite, non-negative values and densities for every pair of
// directions (both sides of the surface), and its samples are finite directions with finite,
// non-negative densities and values.
void fourier(std::string_view input) {
  std::optional<FourierBsdfTable> table;
  try {
    table = parseFourierBsdf(input, "fuzz.bsdf");
  } catch (const FileError&) {
    return;
  }
  FourierBSDF bsdf(&*table);
  checkLookups([&](const Vector3f& wo, const Vector3f& wi) { return bsdf.f(wo, wi); },
               "a Fourier BSDF value is negative or not finite");
  checkLookups([&](const Vector3f& wo, const Vector3f& wi) { return Spectrum(bsdf.pdf(wo, wi)); },
               "a Fourier BSDF density is negative or not finite");
  for (const Vector3f& wo : lookupDirections())
    for (Vector3f side : {wo, -wo})
      for (Float u0 : {0.0f, 0.3f, 0.999f})
        for (Float u1 : {0.0f, 0.5f, 0.999f}) {
          Vector3f wi;
          Float pdf = -1;
          Spectrum f = bsdf.sampleF(side, &wi, Point2f(u0, u1), &pdf);
          if (!(pdf >= 0) || !std::isfinite(pdf))
            broken("a Fourier BSDF sample's density is negative or not finite");
          if (pdf == 0) continue;
          if (!finiteDirection(wi)) broken("a Fourier BSDF sample's direction is not finite");
          for (int c = 0; c < 3; ++c)
            if (!(f[c] >= 0) || !std::isfinite(f[c]))
              broken("a Fourier BSDF sample's value is negative or not finite");
        }
}

}  // namespace candela::fuzz
