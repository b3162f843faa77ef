#include "media/medium_plugins.h"

#include <cstdint>
#include <string>
#include <vector>

#include "media/exponential_volume.h"
#include "media/grid_density_medium.h"
#include "media/homogeneous_medium.h"
#include "media/homogeneous_volume.h"
#include "media/volume_grid.h"

namespace candela {

namespace {

// ---- Volume regions (pbrt-v2, lrt draft ch. 12)

[[noreturn]] void fail(const MediumInputs& desc, const char* param, const std::string& what) {
  throw SceneError(desc.params.locationOf(param, desc.loc), what);
}

Spectrum nonNegativeSpectrum(const MediumInputs& desc, const char* name) {
  Spectrum s = desc.params.getOneSpectrum(name, Spectrum(0));
  for (int i = 0; i < 3; ++i)
    desc.params.requireInRange(name, s[i], ValueRange::nonNegative(), desc.loc);
  return s;
}

// The phase functions of pbrt 2e §11.1; the rule below words the same list for the table.
const std::vector<std::string> kPhaseNames = {
    "hg", "henyey-greenstein", "schlick", "isotropic", "rayleigh", "mie-hazy", "mie-murky"};
constexpr std::string_view kPhaseRule =
    "one of hg, henyey-greenstein, schlick, isotropic, rayleigh, mie-hazy, mie-murky";

// pbrt-v2 has only Henyey–Greenstein ("g"); "string phase" selects the others (candela's
// extension).
PhaseFunction phaseParam(const MediumInputs& desc) {
  const ParamSet& p = desc.params;
  std::string name = p.getOneString("phase", "hg", kPhaseNames, desc.loc);
  auto g = [&] { return p.getOneFloat("g", 0, ValueRange::between(-1, 1), desc.loc); };
  if (name == "hg" || name == "henyey-greenstein") return PhaseFunction::henyeyGreenstein(g());
  if (name == "schlick") return PhaseFunction::schlick(g());
  if (name == "isotropic") return PhaseFunction::isotropic();
  if (name == "rayleigh") return PhaseFunction::rayleigh();
  if (name == "mie-hazy") return PhaseFunction::mieHazy();
  return PhaseFunction::mieMurky();
}

// What every region reads: its coefficients (pbrt 2e App. C defaults) and its box.
struct RegionCommon {
  RegionCoefficients c;
  Bounds3f extent;
};

RegionCommon readRegionCommon(const MediumInputs& desc) {
  const ParamSet& p = desc.params;
  RegionCommon r;
  r.c.sigmaA = nonNegativeSpectrum(desc, "sigma_a");
  r.c.sigmaS = nonNegativeSpectrum(desc, "sigma_s");
  r.c.Le = nonNegativeSpectrum(desc, "Le");
  r.c.phase = phaseParam(desc);
  Point3f p0 = p.getOnePoint3f("p0", Point3f(0, 0, 0));
  Point3f p1 = p.getOnePoint3f("p1", Point3f(1, 1, 1));
  r.extent = Bounds3f(p0, p1);
  Vector3f size = r.extent.diagonal();
  if (!(size.x > 0 && size.y > 0 && size.z > 0 && size.x < kInfinity && size.y < kInfinity &&
        size.z < kInfinity))
    fail(desc, p.find("p1") ? "p1" : "p0",
         "p0 and p1 must be finite corners of a box of nonzero size on every axis");
  return r;
}

std::unique_ptr<Medium> createHomogeneousVolume(const MediumInputs& desc) {
  RegionCommon r = readRegionCommon(desc);
  return std::make_unique<HomogeneousVolume>(desc.toWorld, r.extent, r.c);
}

std::unique_ptr<Medium> createExponentialVolume(const MediumInputs& desc) {
  const ParamSet& p = desc.params;
  RegionCommon r = readRegionCommon(desc);
  Float a = p.getOneFloat("a", 1, ValueRange::nonNegative(), desc.loc);
  Float b = p.getOneFloat("b", 1, ValueRange::finite(), desc.loc);
  Vector3f up = p.getOneVector3f("updir", Vector3f(0, 1, 0));
  if (!(up.lengthSquared() > 0 && up.lengthSquared() < kInfinity))
    fail(desc, "updir", "updir must be a finite, nonzero vector");
  return std::make_unique<ExponentialVolume>(desc.toWorld, r.extent, r.c, a, b, up);
}

std::unique_ptr<Medium> createVolumeGrid(const MediumInputs& desc) {
  const ParamSet& p = desc.params;
  RegionCommon r = readRegionCommon(desc);
  int n[3];
  const char* names[3] = {"nx", "ny", "nz"};
  for (int i = 0; i < 3; ++i) n[i] = p.getOneInt(names[i], 1, ValueRange::atLeast(1), desc.loc);
  std::vector<Float> density = p.getFloatArray("density");
  long long expected = (long long)n[0] * n[1] * n[2];
  if ((long long)density.size() != expected)
    fail(desc, "density",
         "density has " + std::to_string(density.size()) +
             " values; nx*ny*nz = " + std::to_string(expected));
  for (Float d : density) p.requireInRange("density", d, ValueRange::nonNegative(), desc.loc);
  return std::make_unique<VolumeGrid>(desc.toWorld, r.extent, r.c, n[0], n[1], n[2],
                                      std::move(density));
}

// ---- Named media (pbrt-v3, MakeNamedMedium)

// What both media read, scaled by "scale".
struct MediumCoefficients {
  Spectrum sigmaA, sigmaS;
  Float g;
};

MediumCoefficients readMediumCoefficients(const MediumInputs& d) {
  const ParamSet& p = d.params;
  if (p.find("preset"))
    fail(d, "preset",
         "measured medium presets (\"string preset\") are not supported; give "
         "sigma_a and sigma_s");
  // pbrt-v3's defaults (its GetMediumScatteringProperties fallback), per mm^-1 of the medium's
  // space.
  MediumCoefficients m;
  m.sigmaA = p.getOneSpectrum("sigma_a", Spectrum(0.0011f, 0.0024f, 0.014f));
  m.sigmaS = p.getOneSpectrum("sigma_s", Spectrum(2.55f, 3.21f, 3.77f));
  Float scale = p.getOneFloat("scale", 1, ValueRange::nonNegative(), d.loc);
  m.g = p.getOneFloat("g", 0, ValueRange::between(-1, 1), d.loc);
  for (int c = 0; c < 3; ++c) {
    p.requireInRange("sigma_a", m.sigmaA[c], ValueRange::nonNegative(), d.loc);
    p.requireInRange("sigma_s", m.sigmaS[c], ValueRange::nonNegative(), d.loc);
  }
  m.sigmaA *= scale;
  m.sigmaS *= scale;
  return m;
}

std::unique_ptr<Medium> createHomogeneousMedium(const MediumInputs& d) {
  MediumCoefficients m = readMediumCoefficients(d);
  return std::make_unique<HomogeneousMedium>(m.sigmaA, m.sigmaS, m.g);
}

std::unique_ptr<Medium> createHeterogeneousMedium(const MediumInputs& d) {
  const ParamSet& p = d.params;
  MediumCoefficients m = readMediumCoefficients(d);
  int nx = p.getOneInt("nx", 1, ValueRange::atLeast(1), d.loc);
  int ny = p.getOneInt("ny", 1, ValueRange::atLeast(1), d.loc);
  int nz = p.getOneInt("nz", 1, ValueRange::atLeast(1), d.loc);
  constexpr int64_t kMaxSamples = int64_t(1) << 30;
  int64_t count = int64_t(nx) * ny * nz;
  if (count > kMaxSamples) fail(d, "nx", "nx * ny * nz must be at most 2^30");
  std::vector<Float> density = p.getFloatArray("density");
  if (!p.find("density")) fail(d, "density", "heterogeneous medium needs \"float density\"");
  if (int64_t(density.size()) != count)
    fail(d, "density",
         "\"density\" has " + std::to_string(density.size()) +
             " values; nx * ny * nz = " + std::to_string(count));
  for (Float v : density) p.requireInRange("density", v, ValueRange::nonNegative(), d.loc);
  Point3f p0 = p.getOnePoint3f("p0", Point3f(0, 0, 0));
  Point3f p1 = p.getOnePoint3f("p1", Point3f(1, 1, 1));
  if (!(p0.x < p1.x && p0.y < p1.y && p0.z < p1.z))
    fail(d, p.find("p1") ? "p1" : "p0", "p0 must be below p1 on every axis");
  return std::make_unique<GridDensityMedium>(m.sigmaA, m.sigmaS, m.g, nx, ny, nz,
                                             std::move(density), p0, p1, d.toWorld);
}

// ---- The tables

constexpr std::string_view kNonNegative = "non-negative and finite";
constexpr std::string_view kAtLeast1 = "at least 1";
constexpr std::string_view kOpenUnit = "within (-1, 1)";
constexpr unsigned kV2 = kLrt | kPbrtV2;

constexpr std::array<ParamSpec, 7> kRegionParams = {
    {{"sigma_a", "spectrum", "0 0 0", "", kNonNegative, kV2, "absorption per unit length"},
     {"sigma_s", "spectrum", "0 0 0", "", kNonNegative, kV2, "scattering per unit length"},
     {"Le", "spectrum", "0 0 0", "", kNonNegative, kV2, "emitted radiance per unit length"},
     {"phase", "string", "hg", "", kPhaseRule, kCandela, "phase function"},
     {"g", "float", "0", "", kOpenUnit, kV2, "asymmetry of the hg and schlick phase functions"},
     {"p0", "point3", "0 0 0", "", "", kV2, "lower corner of the box"},
     {"p1", "point3", "1 1 1", "", "", kV2, "upper corner of the box"}}};
// The same, then the region's own.
constexpr auto kExponentialParams =
    joinParams(kRegionParams,
               std::to_array<ParamSpec>({
                   {"a", "float", "1", "", kNonNegative, kV2, "density at p0"},
                   {"b", "float", "1", "", "finite", kV2, "falloff rate with height"},
                   {"updir", "vector3", "0 1 0", "", "", kV2, "direction height is measured along"},
               }));
constexpr auto kGridParams =
    joinParams(kRegionParams, std::to_array<ParamSpec>({
                                  {"nx", "integer", "1", "", kAtLeast1, kV2, "samples along x"},
                                  {"ny", "integer", "1", "", kAtLeast1, kV2, "samples along y"},
                                  {"nz", "integer", "1", "", kAtLeast1, kV2, "samples along z"},
                                  {"density", "float[]", "(required)", "", kNonNegative, kV2,
                                   "nx*ny*nz densities, x fastest"},
                              }));

constexpr VolumeRegionPlugin kRegions[] = {
    {{"volume region", "homogeneous", kV2,
      "constant coefficients in a box (lrt draft §12.2; pbrt 2e §11.3.1)", kRegionParams},
     createHomogeneousVolume},
    {{"volume region", "exponential", kV2,
      "density falling off exponentially with height (lrt draft §12.3.1; pbrt 2e §11.3.3)",
      kExponentialParams},
     createExponentialVolume},
    {{"volume region", "volumegrid", kV2,
      "trilinearly interpolated grid of densities (lrt draft §12.3.2; pbrt 2e §11.3.2)",
      kGridParams},
     createVolumeGrid},
};

constexpr ParamSpec kHomogeneousMediumParams[] = {
    {"preset", "string", "(none)", "", "", kPbrtV3, "measured preset: not supported, an error"},
    {"sigma_a", "spectrum", "0.0011 0.0024 0.014", "", kNonNegative, kPbrtV3,
     "absorption per unit length, before scale"},
    {"sigma_s", "spectrum", "2.55 3.21 3.77", "", kNonNegative, kPbrtV3,
     "scattering per unit length, before scale"},
    {"scale", "float", "1", "", kNonNegative, kPbrtV3, "multiplies sigma_a and sigma_s"},
    {"g", "float", "0", "", kOpenUnit, kPbrtV3, "Henyey-Greenstein asymmetry"}};
constexpr ParamSpec kHeterogeneousMediumParams[] = {
    kHomogeneousMediumParams[0],
    kHomogeneousMediumParams[1],
    kHomogeneousMediumParams[2],
    kHomogeneousMediumParams[3],
    kHomogeneousMediumParams[4],
    {"nx", "integer", "1", "", kAtLeast1, kPbrtV3, "samples along x"},
    {"ny", "integer", "1", "", kAtLeast1, kPbrtV3, "samples along y"},
    {"nz", "integer", "1", "", kAtLeast1, kPbrtV3, "samples along z"},
    {"density", "float[]", "(required)", "", kNonNegative, kPbrtV3,
     "nx*ny*nz densities, x fastest"},
    {"p0", "point3", "0 0 0", "", "", kPbrtV3, "lower corner of the grid's box"},
    {"p1", "point3", "1 1 1", "", "", kPbrtV3, "upper corner of the grid's box"}};

constexpr MediumPlugin kMedia[] = {
    {{"medium", "homogeneous", kPbrtV3, "the same coefficients everywhere (pbrt 3e §11.3)",
      kHomogeneousMediumParams},
     createHomogeneousMedium},
    {{"medium", "heterogeneous", kPbrtV3,
      "coefficients scaled by a grid of densities in a box (pbrt 3e §11.3)",
      kHeterogeneousMediumParams},
     createHeterogeneousMedium},
};

}  // namespace

std::span<const VolumeRegionPlugin> volumeRegionPlugins() { return kRegions; }

std::span<const MediumPlugin> mediumPlugins() { return kMedia; }

}  // namespace candela
