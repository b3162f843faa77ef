// The perspective (pinhole or thin-lens) camera (lrt draft §6.2; pbrt-v2 PerspectiveCamera).
// Raster (0,0) is the image's top-left corner; the screen window spans the image, and the fov is
// the angle the window's [-1, 1] range subtends, so by default it applies to the shorter axis.
#pragma once

#include "cameras/camera.h"
#include "core/bounds.h"

namespace candela {

struct PerspectiveCameraOptions {
  Point2i fullResolution{640, 480};
  Bounds2f screenWindow{Point2f(-4.f / 3.f, -1), Point2f(4.f / 3.f, 1)};
  Float fov = 90;  // degrees, across the screen window's [-1, 1]
  Float lensRadius = 0;
  Float focalDistance = 1e30f;
  Float shutterOpen = 0, shutterClose = 1;
  Float hither = 1e-3f, yon = 1e30f;
};

// The default screen window for a frame aspect ratio (width / height): [-1, 1] along the shorter
// axis and [-aspect, aspect] (or [-1/aspect, 1/aspect]) along the longer one.
Bounds2f defaultScreenWindow(Float frameAspectRatio);

class PerspectiveCamera final : public Camera {
 public:
  PerspectiveCamera(const Transform& cameraToWorld, const PerspectiveCameraOptions& options);
  Float generateRay(const CameraSample& sample, Ray* ray) const override;
  // Analytic: the x and y rays start from the film point one pixel over, through the same lens
  // point (pbrt 3e §6.2.3).
  Float generateRayDifferential(const CameraSample& sample, RayDifferential* ray) const override;

  const Transform& cameraToWorld() const { return cameraToWorld_; }
  const PerspectiveCameraOptions& options() const { return options_; }
  Float shutterOpen() const { return options_.shutterOpen; }
  Float shutterClose() const { return options_.shutterClose; }

 private:
  // Camera-space point on the z = 1 plane for a raster position.
  Point3f rasterToCamera(const Point2f& pRaster) const;
  // The camera-space ray through pCamera (on z = 1) and the lens point for u, moved up to the
  // hither plane; *tMax is where it meets the yon plane.
  void cameraSpaceRay(const Point3f& pCamera, const Point2f& uLens, Point3f* o, Vector3f* d,
                      Float* tMax) const;
  // To world space with a unit direction (cameraToWorld may scale).
  Ray toWorld(const Point3f& o, const Vector3f& d, Float tMax, Float time) const;

  Transform cameraToWorld_;
  PerspectiveCameraOptions options_;
  // Raster -> camera on z = 1 is affine: x = originX + raster.x * dxCamera.x, likewise y.
  Point3f rasterOrigin_;
  Vector3f dxCamera_, dyCamera_;
};

}  // namespace candela
