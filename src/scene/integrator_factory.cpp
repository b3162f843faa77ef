// SurfaceIntegrator / Integrator "name" -> SurfaceIntegrator.
#include "integrators/direct_lighting.h"
#include "integrators/path.h"
#include "scene/plugin_factories.h"

namespace candela {

std::unique_ptr<SurfaceIntegrator> createSurfaceIntegrator(const PluginDesc& desc) {
  const ParamSet& p = desc.params;
  int maxDepth = p.getOneInt("maxdepth", 5);
  if (maxDepth < 0) throw SceneError(p.locationOf("maxdepth", desc.loc), "maxdepth must be >= 0");
  if (desc.name == "directlighting") {
    std::string strategy = p.getOneString("strategy", "all");
    DirectLightingIntegrator::Strategy s;
    if (strategy == "all")
      s = DirectLightingIntegrator::Strategy::All;
    else if (strategy == "one")
      s = DirectLightingIntegrator::Strategy::One;
    else
      throw SceneError(p.locationOf("strategy", desc.loc),
                       "unknown strategy '" + strategy + "' (known: all, one)");
    return std::make_unique<DirectLightingIntegrator>(s, maxDepth);
  }
  if (desc.name == "path") return std::make_unique<PathIntegrator>(maxDepth);
  throwUnknownPlugin(desc.loc, "surface integrator", desc.name, {"directlighting", "path"});
}

}  // namespace candela
