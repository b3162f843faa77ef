// Virtual point lights for instant global illumination (Keller's instant radiosity; pbrt 2e
// §15.4): light paths traced from the real lights leave, at every vertex that is not purely
// specular, a point that reflects the light that reached it. Gathering from them at a shading
// point estimates the light that arrives after one or more bounces.
#pragma once

#include <cstddef>
#include <vector>

#include "core/interaction.h"
#include "core/spectrum.h"
#include "scene/scene.h"

namespace candela {

struct VirtualPointLight {
  // Position, error bound and the geometric normal turned to the side the light arrived from;
  // the point emits only into that hemisphere.
  Interaction at;
  // Radiance leaving the point toward any direction of that hemisphere, times the area measure:
  // the path throughput (flux per path) times rho_hd / pi. Divided by the paths per set, summed
  // over a set, f G contribution estimates the bounced light.
  Spectrum contribution;
};

struct VirtualPointLightSets {
  std::vector<std::vector<VirtualPointLight>> sets;
  int pathsPerSet = 0;
  size_t count() const;
  size_t memoryBytes() const;
};

struct VirtualPointLightOptions {
  uint64_t seed = 0;                        // the render's seed
  Float shutterOpen = 0, shutterClose = 0;  // the paths' times are spread over this interval
};

// nSets sets of pathsPerSet light paths each. Path i of set s takes its light choice, origin,
// direction and time from radical inverses of index s * pathsPerSet + i, scrambled by the seed,
// and the rest of its numbers from a generator seeded by (seed, s, i), so the sets depend on
// nothing but the scene and the options.
VirtualPointLightSets traceVirtualPointLights(const Scene& scene, int nSets, int pathsPerSet,
                                              const VirtualPointLightOptions& options);

}  // namespace candela
