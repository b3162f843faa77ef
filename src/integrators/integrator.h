// Surface integrators (lrt draft ch. 16; pbrt 2e ch. 15): the radiance arriving along a camera
// ray. An integrator is shared by all threads and so is const; per-thread state travels in
// the sampler, the arena and the counters.
#pragma once

#include <string>
#include <vector>

#include "core/memory.h"
#include "film/image_buffer.h"
#include "samplers/sampler.h"
#include "scene/scene.h"

namespace candela {

class SplatBuffer;
class Film;

// An image an integrator makes besides the film's (bdpt's per-strategy images), written next to
// the output under its name.
struct NamedImage {
  std::string name;
  ImageBuffer image;
};

struct IntegratorContext {
  Sampler& sampler;
  MemoryArena& arena;
  RayStats& stats;
  // Where an integrator that splats() adds light landing on other pixels; null otherwise.
  SplatBuffer* splats = nullptr;
};

class SurfaceIntegrator {
 public:
  virtual ~SurfaceIntegrator() = default;
  virtual void preprocess(const Scene&) {}
  // Whether Li also adds light to other pixels through ctx.splats (light tracing). The renderer
  // then takes every pixel's samples, those outside the crop window too (see SamplerRenderer).
  virtual bool splats() const { return false; }
  // Images to write besides the film's once rendering is done (film: the render's, for its pixel
  // bounds and scale).
  virtual std::vector<NamedImage> extraImages(const Film& /*film*/) const { return {}; }
  // *alpha is set to 1 when the ray hits a surface and 0 when it escapes.
  virtual Spectrum Li(const RayDifferential& ray, const Scene& scene, IntegratorContext& ctx,
                      Float* alpha) const = 0;
};

}  // namespace candela
