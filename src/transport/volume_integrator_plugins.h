// The table of pbrt-v2's VolumeIntegrator names (issue 34: one home per plug-in): each one's
// dialects, parameters and create function. The build (assembly/volume_factory.cpp) dispatches
// through it, and unknown-name errors, `candela --list-plugins` and `candela --describe` read it.
#pragma once

#include <memory>
#include <span>

#include "core/paramset.h"
#include "core/plugin_spec.h"
#include "transport/volume_integrator.h"

namespace candela {

// Bad values are SceneErrors at the parameter, or at loc.
using VolumeIntegratorCreate = std::unique_ptr<VolumeIntegrator> (*)(const ParamSet& params,
                                                                     const FileLoc& loc);

struct VolumeIntegratorPlugin {
  PluginSpec spec;
  VolumeIntegratorCreate create;
};

std::span<const VolumeIntegratorPlugin> volumeIntegratorPlugins();

}  // namespace candela
