// The samplers' table (issue 34: one home per plug-in): each sampler's name, dialects, parameters
// and create function. createSampler dispatches through it, and unknown-name errors, `candela
// --list-plugins` and `candela --describe` read it.
#pragma once

#include <cstdint>
#include <memory>
#include <span>

#include "core/plugin_spec.h"
#include "samplers/sampler.h"

namespace candela {

// Large enough for any practical render, small enough that counts and indices fit in 32 bits.
inline constexpr int kMaxSamplesPerPixel = 1 << 24;

// What every sampler is made from: its parameters, the seed, sppOverride (0: the scene's count;
// else in [1, kMaxSamplesPerPixel], checked by createSampler), where to send warnings (empty:
// standard error) and the dialect's defaults. Bad values are SceneErrors at the parameter or loc.
using SamplerCreate = std::unique_ptr<Sampler> (*)(const ParamSet& params, uint64_t seed,
                                                   int sppOverride, const FileLoc& loc,
                                                   const SamplerWarning& warn,
                                                   SamplerDefaults defaults);

struct SamplerPlugin {
  PluginSpec spec;
  SamplerCreate create;
};

std::span<const SamplerPlugin> samplerPlugins();

}  // namespace candela
