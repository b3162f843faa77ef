// Cameras (lrt draft ch. 6): turn a CameraSample into a world-space ray. pbrt's conventions:
// left-handed camera space looking down +z, fov along the shorter image axis.
#pragma once

#include <memory>
#include <string>

#include "core/animated_transform.h"
#include "core/paramset.h"
#include "samplers/sampler.h"

namespace candela {

class Camera {
 public:
  virtual ~Camera() = default;
  // Returns the ray's weight (0: no ray); the direction is unit length.
  virtual Float generateRay(const CameraSample& sample, Ray* ray) const = 0;
  // Also fills the offset rays one pixel over in x and y. The default calls generateRay three
  // times.
  virtual Float generateRayDifferential(const CameraSample& sample, RayDifferential* ray) const;
  // The times the camera's rays span (prepasses such as photon shooting sample the same).
  virtual Float shutterOpen() const { return 0; }
  virtual Float shutterClose() const { return 0; }
};

// The camera named by a Camera statement ("perspective", "orthographic" or "environment"), with
// pbrt-v2's parameters and defaults; cameraToWorld is the inverse of the CTM at the statement at
// the two transform times, fullResolution the film's. A moving camera takes each ray to world
// space by the transform at the ray's time (pbrt 2e §6.1). An unknown name or a bad value is a
// SceneError at loc.
std::unique_ptr<Camera> createCamera(const std::string& name, const ParamSet& params,
                                     const AnimatedTransform& cameraToWorld,
                                     const Point2i& fullResolution, const FileLoc& loc);
// A camera that stands still.
std::unique_ptr<Camera> createCamera(const std::string& name, const ParamSet& params,
                                     const Transform& cameraToWorld, const Point2i& fullResolution,
                                     const FileLoc& loc);

}  // namespace candela
