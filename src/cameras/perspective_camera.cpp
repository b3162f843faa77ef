#include "cameras/perspective_camera.h"

#include "core/sampling.h"

namespace candela {

Bounds2f defaultScreenWindow(Float frameAspectRatio) {
  if (frameAspectRatio > 1)
    return Bounds2f(Point2f(-frameAspectRatio, -1), Point2f(frameAspectRatio, 1));
  return Bounds2f(Point2f(-1, -1 / frameAspectRatio), Point2f(1, 1 / frameAspectRatio));
}

PerspectiveCamera::PerspectiveCamera(const Transform& cameraToWorld,
                                     const PerspectiveCameraOptions& options)
    : cameraToWorld_(cameraToWorld), options_(options) {
  // The projection Scale(1/tan(fov/2)) maps camera (x, y, 1) to screen (x, y) / tan(fov/2)
  // (lrt draft §6.2.1); screen to raster flips y so that raster y grows downwards (§6.1). The
  // composition, inverted, is affine on the z = 1 plane, so it is computed directly rather than
  // through the 4x4 projective matrix, which loses precision for a far yon.
  Float tanHalf = std::tan(radians(options.fov) / 2);
  const Bounds2f& sw = options.screenWindow;
  Float xres = Float(options.fullResolution.x), yres = Float(options.fullResolution.y);
  rasterOrigin_ = Point3f(sw.pMin.x * tanHalf, sw.pMax.y * tanHalf, 1);
  dxCamera_ = Vector3f((sw.pMax.x - sw.pMin.x) / xres * tanHalf, 0, 0);
  dyCamera_ = Vector3f(0, -(sw.pMax.y - sw.pMin.y) / yres * tanHalf, 0);
}

Point3f PerspectiveCamera::rasterToCamera(const Point2f& pRaster) const {
  return Point3f(rasterOrigin_.x + pRaster.x * dxCamera_.x,
                 rasterOrigin_.y + pRaster.y * dyCamera_.y, 1);
}

void PerspectiveCamera::cameraSpaceRay(const Point3f& pCamera, const Point2f& uLens, Point3f* o,
                                       Vector3f* d, Float* tMax) const {
  Point3f origin(0, 0, 0);
  Vector3f dir = normalize(Vector3f(pCamera));
  if (options_.lensRadius > 0) {
    // Thin lens (lrt draft §6.2.3): every ray from the film point through the lens meets the
    // pinhole ray on the plane of focus z = focalDistance.
    Point2f pLens = sampleUniformDiskConcentric(uLens) * options_.lensRadius;
    Point3f pFocus = Point3f(pCamera.x, pCamera.y, 1) * options_.focalDistance;
    origin = Point3f(pLens.x, pLens.y, 0);
    dir = normalize(pFocus - origin);
  }
  // Start at the hither plane and stop at the yon plane (lrt draft §6.1: clipping planes).
  Float tHither = options_.hither / dir.z;
  *o = origin + dir * tHither;
  *d = dir;
  *tMax = (options_.yon - options_.hither) / dir.z;
}

Ray PerspectiveCamera::toWorld(const Point3f& o, const Vector3f& d, Float tMax, Float time) const {
  Vector3f dw = cameraToWorld_(d);
  Float len = dw.length();
  return Ray(cameraToWorld_(o), dw / len, tMax * len, time);
}

Float PerspectiveCamera::generateRay(const CameraSample& sample, Ray* ray) const {
  Point3f o;
  Vector3f d;
  Float tMax;
  cameraSpaceRay(rasterToCamera(sample.pFilm), sample.pLens, &o, &d, &tMax);
  Float time = lerp(sample.time, options_.shutterOpen, options_.shutterClose);
  *ray = toWorld(o, d, tMax, time);
  return 1;
}

Float PerspectiveCamera::generateRayDifferential(const CameraSample& sample,
                                                 RayDifferential* ray) const {
  Point3f pCamera = rasterToCamera(sample.pFilm);
  Float time = lerp(sample.time, options_.shutterOpen, options_.shutterClose);
  Point3f o;
  Vector3f d;
  Float tMax;
  cameraSpaceRay(pCamera, sample.pLens, &o, &d, &tMax);
  *ray = RayDifferential(toWorld(o, d, tMax, time));
  Float unused;
  cameraSpaceRay(pCamera + dxCamera_, sample.pLens, &o, &d, &unused);
  Ray rx = toWorld(o, d, kInfinity, time);
  cameraSpaceRay(pCamera + dyCamera_, sample.pLens, &o, &d, &unused);
  Ray ry = toWorld(o, d, kInfinity, time);
  ray->rxOrigin = rx.o;
  ray->rxDirection = rx.d;
  ray->ryOrigin = ry.o;
  ray->ryDirection = ry.d;
  ray->hasDifferentials = true;
  return 1;
}

}  // namespace candela
