#include "assembly/sppm_factory.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "renderers/sppm_renderer.h"

namespace candela {

std::unique_ptr<ImageRenderer> createSppmRenderer(const PluginDesc& desc,
                                                  const ImageRendererContext& context) {
  const ParamSet& p = desc.params;
  auto fail = [&](const char* name, const std::string& what) {
    throw SceneError(p.locationOf(name, desc.loc), std::string(name).append(" ").append(what));
  };
  SppmSettings s;
  s.iterations = p.getOneInt("numiterations", 64);
  if (s.iterations < 1) fail("numiterations", "must be >= 1");
  s.maxDepth = p.getOneInt("maxdepth", 5);
  if (s.maxDepth < 0) fail("maxdepth", "must be >= 0");
  s.photonsPerIteration = p.getOneInt("photonsperiteration", -1);
  if (s.photonsPerIteration == 0 || s.photonsPerIteration < -1)
    fail("photonsperiteration", "must be >= 1, or -1 for the image's pixel count");
  s.initialRadius = p.getOneFloat("radius", 1);
  if (!(s.initialRadius > 0) || !std::isfinite(s.initialRadius)) fail("radius", "must be > 0");
  (void)p.getOneInt("imagewritefrequency", std::numeric_limits<int>::max());
  if (context.sppOverride > 0)
    s.iterations = context.sppOverride;
  else if (context.quick)
    s.iterations = std::max(1, s.iterations / 16);
  s.seed = context.seed;
  return std::make_unique<SppmRenderer>(s);
}

}  // namespace candela
