// Surface integrators (lrt draft ch. 16; pbrt 2e ch. 15): the radiance arriving along a camera
// ray. An integrator is shared by all threads and so is const; per-thread state travels in
// the sampler, the arena and the counters.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/memory.h"
#include "samplers/sampler.h"
#include "scene/scene.h"

namespace candela {

struct IntegratorContext {
  Sampler& sampler;
  MemoryArena& arena;
  RayStats& stats;
};

class SurfaceIntegrator {
 public:
  virtual ~SurfaceIntegrator() = default;
  virtual void preprocess(const Scene&) {}
  // What the preprocess built, as (name, count) lines for --stats; most integrators build nothing.
  virtual std::vector<std::pair<std::string, long>> preprocessStats() const { return {}; }
  // *alpha is set to 1 when the ray hits a surface and 0 when it escapes.
  virtual Spectrum Li(const RayDifferential& ray, const Scene& scene, IntegratorContext& ctx,
                      Float* alpha) const = 0;
};

}  // namespace candela
