// Sampler "name" -> Sampler through the samplers' table (samplers/sampler_plugins.cpp: pbrt-v2's
// parameter names and defaults, lrt draft App. C, and for the samplers pbrt-v3 added, pbrt-v3's).
#include <string>

#include "samplers/sampler.h"
#include "samplers/sampler_plugins.h"

namespace candela {

std::unique_ptr<Sampler> createSampler(const std::string& name, const ParamSet& params,
                                       uint64_t seed, int sppOverride, const FileLoc& loc,
                                       const SamplerWarning& warn, SamplerDefaults defaults) {
  if (sppOverride < 0)
    throw SceneError(loc, "samples per pixel must be positive, got " + std::to_string(sppOverride));
  if (sppOverride > kMaxSamplesPerPixel)
    throw SceneError(loc, "samples per pixel " + std::to_string(sppOverride) + " is too large");
  const SamplerPlugin& plugin = requirePlugin(samplerPlugins(), "sampler", name, loc);
  return plugin.create(params, seed, sppOverride, loc, warn, defaults);
}

}  // namespace candela
