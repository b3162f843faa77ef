// `Volume "name"` -> Medium and `VolumeIntegrator "name"` -> VolumeIntegrator (lrt draft ch. 12
// and §16.7; pbrt-v2). Bad parameters and unknown names are SceneErrors at their location.
#pragma once

#include <memory>
#include <vector>

#include "media/medium.h"
#include "parser/scene_description.h"
#include "transport/volume_integrator.h"

namespace candela {

// One region, in its volumeToWorld space: the entry of volumeRegionPlugins()
// (media/medium_plugins.h, transport/volume_integrator_plugins.h) that desc.name names.
std::unique_ptr<Medium> createVolumeRegion(const VolumeDesc& desc);

// The medium filling the scene: null without regions, the region itself for one, their
// aggregate for several.
std::unique_ptr<Medium> createSceneVolume(const std::vector<VolumeDesc>& volumes);

// The entry of volumeIntegratorPlugins() that desc.name names.
std::unique_ptr<VolumeIntegrator> createVolumeIntegrator(const PluginDesc& desc);

}  // namespace candela
