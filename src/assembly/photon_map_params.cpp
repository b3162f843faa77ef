#include "assembly/photon_map_params.h"

#include <cmath>
#include <string>

namespace candela {

namespace {

// The lrt draft writes flags as integers ("integer finalgather" [1]); pbrt-v2 as bools.
bool flagParam(const ParamSet& p, const std::string& name, bool def, const FileLoc& fallback) {
  const ParamItem* item = p.find(name);
  if (!item) return def;
  if (item->type == ParamType::Bool && item->bools.size() == 1) return item->bools[0];
  if (item->type == ParamType::Integer && item->ints.size() == 1) return item->ints[0] != 0;
  throw SceneError(p.locationOf(name, fallback),
                   "\"" + name + "\" must be one bool (or the lrt draft's integer 0 or 1)");
}

int countParam(const PluginDesc& desc, const std::string& name, int def, int min) {
  return desc.params.getOneInt(name, def, ValueRange::atLeast(min), desc.loc);
}

}  // namespace

PhotonMapSettings photonMapSettings(const PluginDesc& desc) {
  const ParamSet& p = desc.params;
  PhotonMapSettings s;
  s.causticPhotons = countParam(desc, "causticphotons", s.causticPhotons, 0);
  s.indirectPhotons = countParam(desc, "indirectphotons", s.indirectPhotons, 0);
  s.directPhotons = countParam(desc, "directphotons", s.directPhotons, 0);
  s.nUsed = countParam(desc, "nused", s.nUsed, 1);
  s.nFilter = countParam(desc, "nfilter", s.nFilter, 0);
  s.maxPhotonDepth = countParam(desc, "maxphotondepth", s.maxPhotonDepth, 1);
  s.finalGatherSamples = countParam(desc, "finalgathersamples", s.finalGatherSamples, 1);

  // "maxdepth" is the lrt draft's name for the specular recursion depth.
  bool v2Name = p.find("maxspeculardepth") != nullptr, lrtName = p.find("maxdepth") != nullptr;
  if (v2Name && lrtName)
    throw SceneError(p.locationOf("maxdepth", desc.loc),
                     "give one of \"maxspeculardepth\" and its lrt name \"maxdepth\", not both");
  std::string depthName = lrtName ? "maxdepth" : "maxspeculardepth";
  // The specular part recurses once per level on a worker's stack (see whitted's limit).
  s.maxSpecularDepth =
      p.getOneInt(depthName, s.maxSpecularDepth, ValueRange::within(0, 1000), desc.loc);

  s.maxDist = p.getOneFloat("maxdist", s.maxDist, ValueRange::positive(), desc.loc);
  // The photon lookups compare squared distances.
  if (!std::isfinite(s.maxDist * s.maxDist))
    throw SceneError(p.locationOf("maxdist", desc.loc),
                     "\"maxdist\" must have a finite square (got " + formatNumber(s.maxDist) + ")");
  s.gatherAngle =  // degrees
      p.getOneFloat("gatherangle", s.gatherAngle, ValueRange::between(0, 180), desc.loc);
  s.finalGather = flagParam(p, "finalgather", s.finalGather, desc.loc);
  s.directWithPhotons = flagParam(p, "directwithphotons", s.directWithPhotons, desc.loc);
  return s;
}

}  // namespace candela
