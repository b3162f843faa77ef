#include "integrators/photon_map_params.h"

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

int countParam(const ParamSet& p, const FileLoc& loc, const std::string& name, int def, int min) {
  return p.getOneInt(name, def, ValueRange::atLeast(min), loc);
}

}  // namespace

PhotonMapSettings photonMapSettings(const ParamSet& p, const FileLoc& loc) {
  PhotonMapSettings s;
  s.causticPhotons = countParam(p, loc, "causticphotons", s.causticPhotons, 0);
  s.indirectPhotons = countParam(p, loc, "indirectphotons", s.indirectPhotons, 0);
  s.directPhotons = countParam(p, loc, "directphotons", s.directPhotons, 0);
  s.nUsed = countParam(p, loc, "nused", s.nUsed, 1);
  s.nFilter = countParam(p, loc, "nfilter", s.nFilter, 0);
  s.maxPhotonDepth = countParam(p, loc, "maxphotondepth", s.maxPhotonDepth, 1);
  s.finalGatherSamples = countParam(p, loc, "finalgathersamples", s.finalGatherSamples, 1);

  // "maxdepth" is the lrt draft's name for the specular recursion depth.
  bool v2Name = p.find("maxspeculardepth") != nullptr, lrtName = p.find("maxdepth") != nullptr;
  if (v2Name && lrtName)
    throw SceneError(p.locationOf("maxdepth", loc),
                     "give one of \"maxspeculardepth\" and its lrt name \"maxdepth\", not both");
  std::string depthName = lrtName ? "maxdepth" : "maxspeculardepth";
  // The specular part recurses once per level on a worker's stack (see whitted's limit).
  s.maxSpecularDepth = p.getOneInt(depthName, s.maxSpecularDepth, ValueRange::within(0, 1000), loc);

  s.maxDist = p.getOneFloat("maxdist", s.maxDist, ValueRange::positive(), loc);
  // The photon lookups compare squared distances.
  if (!std::isfinite(s.maxDist * s.maxDist))
    throw SceneError(p.locationOf("maxdist", loc),
                     "\"maxdist\" must have a finite square (got " + formatNumber(s.maxDist) + ")");
  s.gatherAngle =  // degrees
      p.getOneFloat("gatherangle", s.gatherAngle, ValueRange::between(0, 180), loc);
  s.finalGather = flagParam(p, "finalgather", s.finalGather, loc);
  s.directWithPhotons = flagParam(p, "directwithphotons", s.directWithPhotons, loc);
  return s;
}

}  // namespace candela
