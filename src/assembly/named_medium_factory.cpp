#include "assembly/named_medium_factory.h"

#include <cmath>
#include <string>

#include "assembly/plugin_factories.h"
#include "core/error.h"
#include "media/grid_density_medium.h"
#include "media/homogeneous_medium.h"

namespace candela {

std::unique_ptr<Medium> createNamedMedium(const MediumDesc& d) {
  const ParamSet& p = d.params;
  auto fail = [&](const char* name, const std::string& what) {
    throw SceneError(p.locationOf(name, d.loc), what);
  };
  if (d.name != "homogeneous" && d.name != "heterogeneous")
    throwUnknownPlugin(p.locationOf("type", d.loc), "medium type", d.name,
                       {"heterogeneous", "homogeneous"});
  if (p.find("preset"))
    fail("preset",
         "measured medium presets (\"string preset\") are not supported; give "
         "sigma_a and sigma_s");
  // pbrt-v3's defaults (its GetMediumScatteringProperties fallback), per mm^-1 of the medium's
  // space, scaled by "scale".
  Spectrum sigmaA = p.getOneSpectrum("sigma_a", Spectrum(0.0011f, 0.0024f, 0.014f));
  Spectrum sigmaS = p.getOneSpectrum("sigma_s", Spectrum(2.55f, 3.21f, 3.77f));
  Float scale = p.getOneFloat("scale", 1, ValueRange::nonNegative(), d.loc);
  Float g = p.getOneFloat("g", 0, ValueRange::between(-1, 1), d.loc);
  for (int c = 0; c < 3; ++c) {
    p.requireInRange("sigma_a", sigmaA[c], ValueRange::nonNegative(), d.loc);
    p.requireInRange("sigma_s", sigmaS[c], ValueRange::nonNegative(), d.loc);
  }
  sigmaA *= scale;
  sigmaS *= scale;
  if (d.name == "homogeneous") return std::make_unique<HomogeneousMedium>(sigmaA, sigmaS, g);

  int nx = p.getOneInt("nx", 1, ValueRange::atLeast(1), d.loc);
  int ny = p.getOneInt("ny", 1, ValueRange::atLeast(1), d.loc);
  int nz = p.getOneInt("nz", 1, ValueRange::atLeast(1), d.loc);
  constexpr int64_t kMaxSamples = int64_t(1) << 30;
  int64_t count = int64_t(nx) * ny * nz;
  if (count > kMaxSamples) fail("nx", "nx * ny * nz must be at most 2^30");
  std::vector<Float> density = p.getFloatArray("density");
  if (!p.find("density")) fail("density", "heterogeneous medium needs \"float density\"");
  if (int64_t(density.size()) != count)
    fail("density", "\"density\" has " + std::to_string(density.size()) +
                        " values; nx * ny * nz = " + std::to_string(count));
  for (size_t i = 0; i < density.size(); ++i)
    if (!ValueRange::nonNegative().contains(density[i]))
      fail("density", "\"density\" value " + std::to_string(i) + " must be " +
                          ValueRange::nonNegative().describe() + " (got " +
                          formatNumber(density[i]) + ")");
  Point3f p0 = p.getOnePoint3f("p0", Point3f(0, 0, 0));
  Point3f p1 = p.getOnePoint3f("p1", Point3f(1, 1, 1));
  if (!(p0.x < p1.x && p0.y < p1.y && p0.z < p1.z))
    fail(p.find("p1") ? "p1" : "p0", "p0 must be below p1 on every axis");
  return std::make_unique<GridDensityMedium>(sigmaA, sigmaS, g, nx, ny, nz, std::move(density), p0,
                                             p1, d.mediumToWorld);
}

}  // namespace candela
