// The environment camera (lrt draft §6.3; pbrt-v2 EnvironmentCamera): rays in every direction
// from the camera's origin, on a latitude-longitude (equirectangular) image. Raster (x, y) of an
// xres x yres image maps to
//   theta = pi y / yres  (0 at the top row, pi at the bottom),
//   phi   = 2 pi x / xres (0 at the left edge, increasing to the right),
// and to the camera-space direction (sin theta cos phi, cos theta, sin theta sin phi): camera +y
// is up (the image's top row looks along +y), the left edge looks along +x, the image centre
// along -x, a quarter of the way across along +z. These are pbrt-v2's axes, kept so that its
// scenes render the same; note they differ from the projective cameras, which look along +z.
// (The draft calls this projection Mercator's; it is the equirectangular one: theta is linear in
// y.) The hither and yon distances clip the rays as spheres around the origin (draft §6.3).
#pragma once

#include "cameras/camera.h"

namespace candela {

struct EnvironmentCameraOptions {
  Point2i fullResolution{640, 480};
  Float shutterOpen = 0, shutterClose = 1;
  Float hither = 0, yon = 1e30f;
};

class EnvironmentCamera final : public Camera {
 public:
  const char* kind() const override { return "environment"; }
  EnvironmentCamera(const AnimatedTransform& cameraToWorld,
                    const EnvironmentCameraOptions& options);
  Float generateRay(const CameraSample& sample, Ray* ray) const override;
  // The differential rays are the directions one pixel over in x and y, from the same origin.
  Float generateRayDifferential(const CameraSample& sample, RayDifferential* ray) const override;
  // Every ray leaves the camera's origin: there is no lens.
  bool readsLensSample() const override { return false; }

  const EnvironmentCameraOptions& options() const { return options_; }
  Float shutterOpen() const override { return options_.shutterOpen; }
  Float shutterClose() const override { return options_.shutterClose; }
  // Clipping is by the spheres of radius hither and yon around the camera.
  bool clipsAway(const Bounds3f& world) const override;
  const AnimatedTransform& cameraToWorld() const { return cameraToWorld_; }
  // The camera-space unit direction for a raster position (the formulas above).
  Vector3f cameraDirection(const Point2f& pRaster) const;

 private:
  Ray worldRay(const Transform& cameraToWorld, const Point2f& pRaster, Float time) const;
  RayDifferential worldRayDifferential(const Transform& cameraToWorld, const Point2f& pRaster,
                                       Float time) const;

  AnimatedTransform cameraToWorld_;
  EnvironmentCameraOptions options_;
};

}  // namespace candela
