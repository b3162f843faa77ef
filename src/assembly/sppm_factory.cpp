#include "assembly/sppm_factory.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "integrators/sppm/sppm_integrator.h"

namespace candela {

std::unique_ptr<Integrator> createSppmIntegrator(const PluginDesc& desc,
                                                 const WholeImageContext& context) {
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
  if (context.sppOverride > 0)
    s.iterations = context.sppOverride;
  else if (context.quick)
    s.iterations = std::max(1, s.iterations / 16);
  s.seed = context.seed;
  return std::make_unique<SppmIntegrator>(s);
}

}  // namespace candela
