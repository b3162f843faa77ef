// The parameters of SurfaceIntegrator "photonmap" / "exphotonmap": pbrt-v2's names and defaults,
// and the lrt draft's (directphotons, directwithphotons, nfilter, maxdepth for
// maxspeculardepth, integer flags). Bad values are located SceneErrors.
#pragma once

#include "core/paramset.h"
#include "integrators/photon_map_integrator.h"

namespace candela {

PhotonMapSettings photonMapSettings(const ParamSet& params, const FileLoc& loc);

}  // namespace candela
