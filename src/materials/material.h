// Materials turn a surface point into a BSDF (lrt draft ch. 10). BSDFs live in the caller's
// per-sample arena.
#pragma once

#include "core/memory.h"
#include "reflection/bsdf.h"

namespace candela {

class Material {
 public:
  virtual ~Material() = default;
  virtual const BSDF* getBSDF(const SurfaceInteraction& si, MemoryArena& arena) const = 0;
};

}  // namespace candela
