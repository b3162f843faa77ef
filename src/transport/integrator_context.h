// What one thread carries along a path: its sampler, arena and ray counters, and where light
// landing on other pixels and Volume regions' transmittance come from. Integrators are shared by
// all threads and so are const; this is the per-thread state their building blocks take.
#pragma once

#include "core/memory.h"
#include "samplers/halton_sampler.h"
#include "samplers/sampler.h"
#include "scene/scene.h"

namespace candela {

class SplatBuffer;
class VolumeIntegrator;

struct IntegratorContext {
  Sampler& sampler;
  MemoryArena& arena;
  RayStats& stats;
  // Where an integrator that splats light (bdpt's light tracing) adds light landing on other
  // pixels; null otherwise.
  SplatBuffer* splats = nullptr;
  // The volume integrator whose transmittance shadow rays and path segments take when the scene
  // has a volume (see volume_transmittance.h); null otherwise.
  const VolumeIntegrator* volumeIntegrator = nullptr;
  // The sampler when it is the Halton sampler (a final class), else null: through get1D and get2D
  // below its values are then computed inline, not through a virtual call, which was a large
  // part of the few nanoseconds a value takes.
  HaltonSampler* halton = dynamic_cast<HaltonSampler*>(&sampler);

  // The sampler's next values: sampler.get1D() and sampler.get2D().
  Float get1D() { return halton ? halton->get1D() : sampler.get1D(); }
  Point2f get2D() { return halton ? halton->get2D() : sampler.get2D(); }
  void skip1D() { halton ? halton->skip1D() : sampler.skip1D(); }  // see Sampler::skip1D
};

}  // namespace candela
