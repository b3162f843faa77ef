// The tables of pbrt-v2's Volume regions and VolumeIntegrators and of pbrt-v3's named media
// (MakeNamedMedium "string type"), issue 34's one home per plug-in: each one's dialects,
// parameters with their defaults and rules, and its create function. createVolumeRegion,
// createVolumeIntegrator (assembly/volume_factory.cpp) and createNamedMedium
// (assembly/named_medium_factory.cpp) dispatch through them, and unknown-name errors, `candela
// --list-plugins` and `candela --describe` read them.
#pragma once

#include <memory>
#include <span>

#include "core/plugin_spec.h"
#include "media/medium.h"
#include "parser/scene_description.h"
#include "transport/volume_integrator.h"

namespace candela {

// Bad values are SceneErrors at the parameter, or at desc.loc.

// One region in its volumeToWorld space.
using VolumeRegionCreate = std::unique_ptr<Medium> (*)(const VolumeDesc& desc);

struct VolumeRegionPlugin {
  PluginSpec spec;
  VolumeRegionCreate create;
};

std::span<const VolumeRegionPlugin> volumeRegionPlugins();

using VolumeIntegratorCreate = std::unique_ptr<VolumeIntegrator> (*)(const PluginDesc& desc);

struct VolumeIntegratorPlugin {
  PluginSpec spec;
  VolumeIntegratorCreate create;
};

std::span<const VolumeIntegratorPlugin> volumeIntegratorPlugins();

// A medium in its mediumToWorld space; desc.name is the statement's "type".
using MediumCreate = std::unique_ptr<Medium> (*)(const MediumDesc& desc);

struct MediumPlugin {
  PluginSpec spec;
  MediumCreate create;
};

std::span<const MediumPlugin> mediumPlugins();

}  // namespace candela
