// Cameras (lrt draft ch. 6): turn a CameraSample into a world-space ray. pbrt's conventions:
// left-handed camera space looking down +z, fov along the shorter image axis.
#pragma once

#include "core/transform.h"
#include "samplers/sampler.h"

namespace candela {

class Camera {
 public:
  virtual ~Camera() = default;
  // Returns the ray's weight (0: no ray); the direction is unit length.
  virtual Float generateRay(const CameraSample& sample, Ray* ray) const = 0;
  // Also fills the offset rays one pixel over in x and y. The default calls generateRay three times.
  virtual Float generateRayDifferential(const CameraSample& sample, RayDifferential* ray) const;
};

}  // namespace candela
