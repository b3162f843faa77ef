// Integrator "sppm" (pbrt-v3): its parameters, checked. pbrt-v3's names and defaults: "integer
// numiterations" 64, "integer maxdepth" 5, "integer photonsperiteration" -1 (the full image's
// pixel count), "float radius" 1 (the initial search radius, in scene units), "integer
// imagewritefrequency" (accepted and ignored: the progressive passes and --error-log report the
// image as it converges). --spp replaces numiterations; --quick divides it by 16 (pbrt-v3's rule).
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "integrators/integrator_plugins.h"
#include "integrators/sppm/sppm_integrator.h"

namespace candela {

std::unique_ptr<Integrator> createSppmIntegrator(const IntegratorInputs& desc) {
  const ParamSet& p = desc.params;
  SppmSettings s;
  s.iterations = p.getOneInt("numiterations", 64, ValueRange::atLeast(1), desc.loc);
  s.maxDepth = p.getOneInt("maxdepth", 5, ValueRange::atLeast(0), desc.loc);
  // -1 or at least 1: no one range, so 0 is refused on its own.
  s.photonsPerIteration = p.getOneInt("photonsperiteration", -1, ValueRange::atLeast(-1), desc.loc);
  if (s.photonsPerIteration == 0)
    throw SceneError(p.locationOf("photonsperiteration", desc.loc),
                     "\"photonsperiteration\" must be at least 1, or -1 for the image's pixel "
                     "count (got 0)");
  s.initialRadius = p.getOneFloat("radius", 1, ValueRange::positive(), desc.loc);
  (void)p.getOneInt("imagewritefrequency", std::numeric_limits<int>::max());
  if (desc.sppOverride > 0)
    s.iterations = desc.sppOverride;
  else if (desc.quick)
    s.iterations = std::max(1, s.iterations / 16);
  s.seed = desc.seed;
  return std::make_unique<SppmIntegrator>(s);
}

}  // namespace candela
