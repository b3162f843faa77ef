#include "assembly/volume_factory.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "assembly/plugin_factories.h"
#include "media/aggregate_volume.h"
#include "media/exponential_volume.h"
#include "media/homogeneous_volume.h"
#include "media/volume_grid.h"

namespace candela {

namespace {

[[noreturn]] void fail(const PluginDesc& desc, const char* param, const std::string& what) {
  throw SceneError(desc.params.locationOf(param, desc.loc), what);
}

Spectrum nonNegativeSpectrum(const PluginDesc& desc, const char* name) {
  Spectrum s = desc.params.getOneSpectrum(name, Spectrum(0));
  for (int i = 0; i < 3; ++i)
    desc.params.requireInRange(name, s[i], ValueRange::nonNegative(), desc.loc);
  return s;
}

// pbrt-v2 has only Henyey–Greenstein ("g"); "string phase" selects the others (candela's
// extension): the phase functions of pbrt 2e §11.1.
PhaseFunction phaseParam(const PluginDesc& desc) {
  const ParamSet& p = desc.params;
  std::string name = p.getOneString("phase", "hg");
  auto g = [&] { return p.getOneFloat("g", 0, ValueRange::between(-1, 1), desc.loc); };
  if (name == "hg" || name == "henyey-greenstein") return PhaseFunction::henyeyGreenstein(g());
  if (name == "schlick") return PhaseFunction::schlick(g());
  if (name == "isotropic") return PhaseFunction::isotropic();
  if (name == "rayleigh") return PhaseFunction::rayleigh();
  if (name == "mie-hazy") return PhaseFunction::mieHazy();
  if (name == "mie-murky") return PhaseFunction::mieMurky();
  fail(desc, "phase",
       "unknown phase function '" + name +
           "' (known: hg, schlick, isotropic, rayleigh, mie-hazy, mie-murky)");
}

}  // namespace

std::unique_ptr<Medium> createVolumeRegion(const VolumeDesc& desc) {
  const ParamSet& p = desc.params;
  static const std::vector<std::string> kKnown = {"homogeneous", "exponential", "volumegrid"};
  if (std::find(kKnown.begin(), kKnown.end(), desc.name) == kKnown.end())
    throwUnknownPlugin(desc.loc, "volume region", desc.name, kKnown);
  // Parameters every region has (pbrt 2e App. C defaults).
  RegionCoefficients c;
  c.sigmaA = nonNegativeSpectrum(desc, "sigma_a");
  c.sigmaS = nonNegativeSpectrum(desc, "sigma_s");
  c.Le = nonNegativeSpectrum(desc, "Le");
  c.phase = phaseParam(desc);
  Point3f p0 = p.getOnePoint3f("p0", Point3f(0, 0, 0));
  Point3f p1 = p.getOnePoint3f("p1", Point3f(1, 1, 1));
  Bounds3f extent(p0, p1);
  Vector3f size = extent.diagonal();
  if (!(size.x > 0 && size.y > 0 && size.z > 0 && size.x < kInfinity && size.y < kInfinity &&
        size.z < kInfinity))
    fail(desc, p.find("p1") ? "p1" : "p0",
         "p0 and p1 must be finite corners of a box of nonzero size on every axis");
  const Transform& toWorld = desc.volumeToWorld;

  if (desc.name == "homogeneous") return std::make_unique<HomogeneousVolume>(toWorld, extent, c);

  if (desc.name == "exponential") {
    Float a = p.getOneFloat("a", 1, ValueRange::nonNegative(), desc.loc);
    Float b = p.getOneFloat("b", 1, ValueRange::finite(), desc.loc);
    Vector3f up = p.getOneVector3f("updir", Vector3f(0, 1, 0));
    if (!(up.lengthSquared() > 0 && up.lengthSquared() < kInfinity))
      fail(desc, "updir", "updir must be a finite, nonzero vector");
    return std::make_unique<ExponentialVolume>(toWorld, extent, c, a, b, up);
  }

  // volumegrid
  int n[3];
  const char* names[3] = {"nx", "ny", "nz"};
  for (int i = 0; i < 3; ++i) {
    n[i] = p.getOneInt(names[i], 1, ValueRange::atLeast(1), desc.loc);
  }
  std::vector<Float> density = p.getFloatArray("density");
  long long expected = (long long)n[0] * n[1] * n[2];
  if ((long long)density.size() != expected)
    fail(desc, "density",
         "density has " + std::to_string(density.size()) +
             " values; nx*ny*nz = " + std::to_string(expected));
  for (size_t i = 0; i < density.size(); ++i)
    if (!ValueRange::nonNegative().contains(density[i]))
      fail(desc, "density",
           "\"density\" value " + std::to_string(i) + " must be " +
               ValueRange::nonNegative().describe() + " (got " + formatNumber(density[i]) + ")");
  return std::make_unique<VolumeGrid>(toWorld, extent, c, n[0], n[1], n[2], std::move(density));
}

std::unique_ptr<Medium> createSceneVolume(const std::vector<VolumeDesc>& volumes) {
  if (volumes.empty()) return nullptr;
  std::vector<std::unique_ptr<Medium>> regions;
  for (const VolumeDesc& v : volumes) regions.push_back(createVolumeRegion(v));
  if (regions.size() == 1) return std::move(regions.front());
  return std::make_unique<AggregateVolume>(std::move(regions));
}

std::unique_ptr<VolumeIntegrator> createVolumeIntegrator(const PluginDesc& desc) {
  static const std::vector<std::string> kKnown = {"emission", "single"};
  if (std::find(kKnown.begin(), kKnown.end(), desc.name) == kKnown.end())
    throwUnknownPlugin(desc.loc, "volume integrator", desc.name, kKnown);
  Float step = desc.params.getOneFloat("stepsize", 1, ValueRange::positive(), desc.loc);
  if (desc.name == "emission") return std::make_unique<EmissionIntegrator>(step);
  return std::make_unique<SingleScatteringIntegrator>(step);
}

}  // namespace candela
