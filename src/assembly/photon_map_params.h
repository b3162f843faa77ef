// The parameters of SurfaceIntegrator "photonmap" / "exphotonmap": pbrt-v2's names and defaults,
// and the lrt draft's (directphotons, directwithphotons, nfilter, maxdepth for
// maxspeculardepth, integer flags). Bad values are located SceneErrors.
#pragma once

#include "integrators/photon_map_integrator.h"
#include "parser/scene_description.h"

namespace candela {

PhotonMapSettings photonMapSettings(const PluginDesc& desc);

}  // namespace candela
