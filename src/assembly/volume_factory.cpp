#include "assembly/volume_factory.h"

#include "media/aggregate_volume.h"
#include "media/medium_plugins.h"
#include "transport/volume_integrator_plugins.h"

namespace candela {

// The regions and integrators themselves, their parameters and their names are the tables of
// media/medium_plugins.cpp and transport/volume_integrator_plugins.cpp.

std::unique_ptr<Medium> createVolumeRegion(const VolumeDesc& desc) {
  return requirePlugin(volumeRegionPlugins(), "volume region", desc.name, desc.loc)
      .create({desc.params, desc.loc, desc.volumeToWorld});
}

std::unique_ptr<Medium> createSceneVolume(const std::vector<VolumeDesc>& volumes) {
  if (volumes.empty()) return nullptr;
  std::vector<std::unique_ptr<Medium>> regions;
  for (const VolumeDesc& v : volumes) regions.push_back(createVolumeRegion(v));
  if (regions.size() == 1) return std::move(regions.front());
  return std::make_unique<AggregateVolume>(std::move(regions));
}

std::unique_ptr<VolumeIntegrator> createVolumeIntegrator(const PluginDesc& desc) {
  return requirePlugin(volumeIntegratorPlugins(), "volume integrator", desc.name, desc.loc)
      .create(desc.params, desc.loc);
}

}  // namespace candela
