// Particle tracing for photon maps (pbrt 2e §15.6.1): paths leave the lights, chosen in proportion
// to their power, and deposit a photon at every non-specular surface they meet. Path i's random
// numbers are a function of (seed, i) alone and paths run in fixed blocks whose results are
// concatenated in index order, so the photons do not depend on the thread count.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "transport/photon_map.h"

namespace candela {

// Where a deposited photon goes, by the path that brought it (pbrt 2e §15.6.1).
enum class PhotonKind {
  Direct,    // first surface the path met
  Caustic,   // after one or more specular bounces only
  Indirect,  // after any other path
};
inline constexpr int kPhotonKinds = 3;

struct PhotonShootingPlan {
  // Photons wanted of each kind (index: PhotonKind); 0 = not collected.
  int64_t wanted[kPhotonKinds] = {0, 0, 0};
  // pbrt-v2's direct photons for radiance photons only: collected, with no count of their own,
  // from the same paths as the indirect photons (wanted[Direct] is then ignored).
  bool directFollowsIndirect = false;
  bool radianceSites = false;  // record radiance-photon sites (final gathering)
  int maxPhotonDepth = 5;      // surface interactions per path
  uint64_t seed = 0;
  Float shutterOpen = 0, shutterClose = 0;  // each path at a time in between, as camera rays
  int nThreads = 0;                         // 0: all cores
  bool showProgress = false;
  std::function<void(const std::string&)> warn;  // may be empty
};

// Where a radiance photon will be (pbrt 2e §15.6.3), with the surface's reflectances.
struct RadiancePhotonSite {
  Point3f p;
  Normal3f n;
  Spectrum rhoR, rhoT;
};

struct ShotPhotons {
  std::vector<Photon> photons;
  uint64_t nPaths = 0;  // paths the photons' weights are divided by
};

struct PhotonShootingResult {
  ShotPhotons maps[kPhotonKinds];
  std::vector<RadiancePhotonSite> radianceSites;
  uint64_t pathsShot = 0;
  RayStats rays;  // traced while shooting
};

PhotonShootingResult shootPhotons(const Scene& scene, const PhotonShootingPlan& plan);

}  // namespace candela
