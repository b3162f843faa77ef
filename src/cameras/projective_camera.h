// Projective cameras (lrt draft §6.1): the perspective and orthographic cameras share the raster
// -> screen mapping, the thin lens, the clipping planes, the shutter and the analytic ray
// differentials; they differ only in the pinhole ray through a screen point. That ray is
// o + t d with o on the lens plane z = 0 and d.z = 1, and both o and d are linear in the screen
// point s:
//   o = (originScale * s, 0),  d = (directionScale * s, 1).
// The perspective camera has originScale 0 and directionScale tan(fov/2) (all rays through the
// pinhole); the orthographic camera has originScale 1 and directionScale 0 (parallel rays).
#pragma once

#include "cameras/camera.h"
#include "core/bounds.h"

namespace candela {

struct ProjectiveCameraOptions {
  Point2i fullResolution{640, 480};
  Bounds2f screenWindow{Point2f(-4.f / 3.f, -1), Point2f(4.f / 3.f, 1)};
  Float lensRadius = 0;
  Float focalDistance = 1e30f;
  Float shutterOpen = 0, shutterClose = 1;
  Float hither = 0, yon = 1e30f;
};

// The default screen window for a frame aspect ratio (width / height): [-1, 1] along the shorter
// axis and [-aspect, aspect] (or [-1/aspect, 1/aspect]) along the longer one (lrt draft App. C).
Bounds2f defaultScreenWindow(Float frameAspectRatio);

class ProjectiveCamera : public Camera {
 public:
  Float generateRay(const CameraSample& sample, Ray* ray) const final;
  // Analytic: the x and y rays start from the raster point one pixel over, through the same lens
  // point (pbrt 3e §6.2.3, §6.2.1).
  Float generateRayDifferential(const CameraSample& sample, RayDifferential* ray) const final;
  bool readsLensSample() const final { return options_.lensRadius > 0; }

  const AnimatedTransform& cameraToWorld() const { return cameraToWorld_; }
  const ProjectiveCameraOptions& projectiveOptions() const { return options_; }
  Float shutterOpen() const override { return options_.shutterOpen; }
  Float shutterClose() const override { return options_.shutterClose; }
  // Clipping is by the planes z = hither and z = yon of camera space.
  bool clipsAway(const Bounds3f& world) const override;

  // Screen space (lrt draft §6.1): raster (0, 0) is the screen window's top-left corner
  // (xmin, ymax), raster (xres, yres) its bottom-right corner (xmax, ymin).
  Point2f rasterToScreen(const Point2f& pRaster) const;

 protected:
  ProjectiveCamera(const AnimatedTransform& cameraToWorld, const ProjectiveCameraOptions& options,
                   Float originScale, Float directionScale);
  // The inverse of pinholeRay's direction map: the raster position of a pinhole ray direction
  // with d.z = 1.
  Point2f rasterOfPinholeDirection(const Vector3f& d) const {
    return Point2f((d.x - d0_.x) / dDx_.x, (d.y - d0_.y) / dDy_.y);
  }
  // The area the film covers on the plane z = 1 (pinhole directions with d.z = 1).
  Float pinholeFilmArea() const {
    return std::abs(dDx_.x * Float(options_.fullResolution.x)) *
           std::abs(dDy_.y * Float(options_.fullResolution.y));
  }
  // cameraToWorld and its inverse at a time (cached when the camera stands still).
  void transformsAt(Float time, Transform* cameraToWorld, Transform* worldToCamera) const;

 private:
  // The camera-space pinhole ray's origin and direction (d.z = 1) for a raster position.
  void pinholeRay(const Point2f& pRaster, Point3f* o, Vector3f* d) const;
  // The ray through the lens point for u that meets the pinhole ray (o, d) on the plane of focus
  // z = focalDistance, normalized and moved up to the hither plane; *tMax reaches the yon plane.
  void lensRay(Point3f o, Vector3f d, const Point2f& uLens, Point3f* origin, Vector3f* dir,
               Float* tMax) const;
  // To world space with a unit direction (cameraToWorld may scale).
  static Ray toWorld(const Transform& cameraToWorld, const Point3f& o, const Vector3f& d,
                     Float tMax, Float time);
  // generateRay and generateRayDifferential under one camera-to-world transform: the camera's
  // own when it stands still, the one at the ray's time when it moves. Everything cached above
  // is in camera space, so it holds at every time.
  Ray cameraRay(const CameraSample& sample, Float time, const Transform& cameraToWorld) const;
  RayDifferential cameraRayDifferential(const CameraSample& sample, Float time,
                                        const Transform& cameraToWorld) const;

  AnimatedTransform cameraToWorld_;
  Transform worldToCameraStill_;  // inverse of cameraToWorld_ when it does not move
  ProjectiveCameraOptions options_;
  // Raster -> pinhole ray is affine: o = o0 + x oDx + y oDy, d = d0 + x dDx + y dDy.
  Point3f o0_;
  Vector3f oDx_, oDy_;
  Vector3f d0_, dDx_, dDy_;
};

}  // namespace candela
