// The tables of pbrt-v2's Volume regions and of pbrt-v3's named media (MakeNamedMedium "string
// type"), issue 34's one home per plug-in: each one's dialects, parameters with their defaults
// and rules, and its create function. The build (assembly/volume_factory.cpp,
// assembly/named_medium_factory.cpp) dispatches through them, and unknown-name errors, `candela
// --list-plugins` and `candela --describe` read them.
#pragma once

#include <memory>
#include <span>

#include "core/paramset.h"
#include "core/plugin_spec.h"
#include "core/transform.h"
#include "media/medium.h"

namespace candela {

// A Volume or MakeNamedMedium statement: its parameters and location, and the CTM there (the
// region's or medium's space to world).
struct MediumInputs {
  const ParamSet& params;
  const FileLoc& loc;
  const Transform& toWorld;
};

// Bad values are SceneErrors at the parameter, or at in.loc.

// One region in its volume-to-world space.
using VolumeRegionCreate = std::unique_ptr<Medium> (*)(const MediumInputs& in);

struct VolumeRegionPlugin {
  PluginSpec spec;
  VolumeRegionCreate create;
};

std::span<const VolumeRegionPlugin> volumeRegionPlugins();

// A medium in its medium-to-world space.
using MediumCreate = std::unique_ptr<Medium> (*)(const MediumInputs& in);

struct MediumPlugin {
  PluginSpec spec;
  MediumCreate create;
};

std::span<const MediumPlugin> mediumPlugins();

}  // namespace candela
