// SurfaceIntegrator / Integrator "name" -> SurfaceIntegrator.
#include "integrators/ambient_occlusion.h"
#include "integrators/direct_lighting.h"
#include "integrators/path.h"
#include "integrators/whitted.h"
#include "scene/photon_map_params.h"
#include "scene/plugin_factories.h"

namespace candela {

namespace {

// "maxdepth" is read only by the integrators that have it, so that anywhere else it is reported
// as unused.
// recursive: the integrator recurses once per level (whitted, directlighting), on a worker
// thread's stack, which two facing mirrors overflow somewhere past 10,000 levels.
int maxDepthParam(const PluginDesc& desc, bool recursive) {
  const ParamSet& p = desc.params;
  int maxDepth = p.getOneInt("maxdepth", 5);
  if (maxDepth < 0) throw SceneError(p.locationOf("maxdepth", desc.loc), "maxdepth must be >= 0");
  constexpr int kMaxRecursion = 1000;
  if (recursive && maxDepth > kMaxRecursion)
    throw SceneError(p.locationOf("maxdepth", desc.loc),
                     std::string("maxdepth must be at most ")
                         .append(std::to_string(kMaxRecursion))
                         .append(" for '")
                         .append(desc.name)
                         .append("', which recurses once per level; got ")
                         .append(std::to_string(maxDepth)));
  return maxDepth;
}

}  // namespace

std::unique_ptr<SurfaceIntegrator> createSurfaceIntegrator(const PluginDesc& desc) {
  const ParamSet& p = desc.params;
  if (desc.name == "directlighting") {
    int maxDepth = maxDepthParam(desc, true);
    std::string strategy = p.getOneString("strategy", "all");
    DirectLightingIntegrator::Strategy s;
    if (strategy == "all")
      s = DirectLightingIntegrator::Strategy::All;
    else if (strategy == "one")
      s = DirectLightingIntegrator::Strategy::One;
    else
      throw SceneError(
          p.locationOf("strategy", desc.loc),
          std::string("unknown strategy '").append(strategy).append("' (known: all, one)"));
    return std::make_unique<DirectLightingIntegrator>(s, maxDepth);
  }
  if (desc.name == "path") return std::make_unique<PathIntegrator>(maxDepthParam(desc, false));
  if (desc.name == "whitted") return std::make_unique<WhittedIntegrator>(maxDepthParam(desc, true));
  if (desc.name == "ambientocclusion") {
    // pbrt-v2's defaults: 2048 directions, unbounded probe rays.
    int nSamples = p.getOneInt("nsamples", 2048);
    if (nSamples < 1) throw SceneError(p.locationOf("nsamples", desc.loc), "nsamples must be >= 1");
    Float maxDist = p.getOneFloat("maxdist", kInfinity);
    if (!(maxDist > 0)) throw SceneError(p.locationOf("maxdist", desc.loc), "maxdist must be > 0");
    // pbrt-v3's switch: cosine-weighted directions (default) or pbrt-v2's uniform ones.
    bool cosSample = p.getOneBool("cossample", true);
    return std::make_unique<AmbientOcclusionIntegrator>(nSamples, maxDist, cosSample);
  }
  // pbrt-v2 registers its photon mapper under both names; nothing differs.
  if (desc.name == "photonmap" || desc.name == "exphotonmap")
    return std::make_unique<PhotonMapIntegrator>(photonMapSettings(desc));
  throwUnknownPlugin(
      desc.loc, "surface integrator", desc.name,
      {"ambientocclusion", "directlighting", "exphotonmap", "path", "photonmap", "whitted"});
}

}  // namespace candela
