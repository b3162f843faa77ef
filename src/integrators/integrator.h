// Surface integrators (lrt draft ch. 16; pbrt 2e ch. 15): the radiance arriving along a camera
// ray. An integrator is shared by all threads and so is const; per-thread state travels in
// the sampler, the arena and the counters.
#pragma once

#include <functional>
#include <map>
#include <string>

#include "core/memory.h"
#include "samplers/sampler.h"
#include "scene/scene.h"

namespace candela {

struct IntegratorContext {
  Sampler& sampler;
  MemoryArena& arena;
  RayStats& stats;
};

// What a preprocess may need from the build besides the scene.
struct PreprocessOptions {
  uint64_t seed = 0;  // the render's seed: a prepass's random numbers derive from it
  int nThreads = 0;   // 0: all cores
  bool showProgress = false;
  bool quick = false;                            // --quick: a cheaper, rougher prepass
  bool sceneHasSpecular = true;                  // some material may scatter perfectly specularly
  Float shutterOpen = 0, shutterClose = 0;       // the camera's: the times a prepass samples
  std::function<void(const std::string&)> warn;  // may be empty
};

class SurfaceIntegrator {
 public:
  virtual ~SurfaceIntegrator() = default;
  virtual void preprocess(const Scene&) {}
  // The build calls this one; integrators that need the options override it.
  virtual void prepare(const Scene& scene, const PreprocessOptions&) { preprocess(scene); }
  // What the preprocess built, for --stats: name -> count.
  virtual std::map<std::string, long> buildCounts() const { return {}; }
  // *alpha is set to 1 when the ray hits a surface and 0 when it escapes.
  virtual Spectrum Li(const RayDifferential& ray, const Scene& scene, IntegratorContext& ctx,
                      Float* alpha) const = 0;
};

}  // namespace candela
