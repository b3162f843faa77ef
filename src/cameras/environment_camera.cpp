#include "cameras/environment_camera.h"

namespace candela {

EnvironmentCamera::EnvironmentCamera(const Transform& cameraToWorld,
                                     const EnvironmentCameraOptions& options)
    : cameraToWorld_(cameraToWorld), options_(options) {}

Vector3f EnvironmentCamera::cameraDirection(const Point2f& pRaster) const {
  Float theta = kPi * pRaster.y / Float(options_.fullResolution.y);
  Float phi = 2 * kPi * pRaster.x / Float(options_.fullResolution.x);
  Float sinTheta = std::sin(theta);
  return Vector3f(sinTheta * std::cos(phi), std::cos(theta), sinTheta * std::sin(phi));
}

Ray EnvironmentCamera::worldRay(const Point2f& pRaster, Float time) const {
  Vector3f d = cameraToWorld_(cameraDirection(pRaster));
  // cameraToWorld may scale: distances along the ray are in camera units, so the clipping
  // radii scale with the direction's length before it is normalized.
  Float len = d.length();
  Point3f origin = cameraToWorld_(Point3f(0, 0, 0));
  Vector3f dir = d / len;
  return Ray(origin + dir * (options_.hither * len), dir, (options_.yon - options_.hither) * len,
             time);
}

Float EnvironmentCamera::generateRay(const CameraSample& sample, Ray* ray) const {
  *ray = worldRay(sample.pFilm, lerp(sample.time, options_.shutterOpen, options_.shutterClose));
  return 1;
}

Float EnvironmentCamera::generateRayDifferential(const CameraSample& sample,
                                                 RayDifferential* ray) const {
  Float time = lerp(sample.time, options_.shutterOpen, options_.shutterClose);
  *ray = RayDifferential(worldRay(sample.pFilm, time));
  Ray rx = worldRay(Point2f(sample.pFilm.x + 1, sample.pFilm.y), time);
  Ray ry = worldRay(Point2f(sample.pFilm.x, sample.pFilm.y + 1), time);
  ray->rxOrigin = rx.o;
  ray->rxDirection = rx.d;
  ray->ryOrigin = ry.o;
  ray->ryDirection = ry.d;
  ray->hasDifferentials = true;
  return 1;
}

}  // namespace candela
