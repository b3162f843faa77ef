#include "cameras/environment_camera.h"

#include <algorithm>

namespace candela {

EnvironmentCamera::EnvironmentCamera(const AnimatedTransform& cameraToWorld,
                                     const EnvironmentCameraOptions& options)
    : cameraToWorld_(cameraToWorld), options_(options) {}

bool EnvironmentCamera::clipsAway(const Bounds3f& world) const {
  if (world.empty()) return false;
  for (Float time : {options_.shutterOpen, options_.shutterClose}) {
    Transform worldToCamera = inverse(cameraToWorld_.interpolate(time));
    // The farthest point of a box is a corner; the nearest is bounded below by the distance to
    // the camera-space box around the corners (so a warning is never given wrongly).
    Bounds3f box;
    Float farthest = 0;
    for (int c = 0; c < 8; ++c) {
      Point3f p = worldToCamera(world.corner(c));
      box = unionOf(box, p);
      farthest = std::max(farthest, Vector3f(p.x, p.y, p.z).length());
    }
    Vector3f nearest(std::max({box.pMin.x, Float(0), -box.pMax.x}),
                     std::max({box.pMin.y, Float(0), -box.pMax.y}),
                     std::max({box.pMin.z, Float(0), -box.pMax.z}));
    if (!(farthest < options_.hither || nearest.length() > options_.yon)) return false;
  }
  return true;
}

Vector3f EnvironmentCamera::cameraDirection(const Point2f& pRaster) const {
  Float theta = kPi * pRaster.y / Float(options_.fullResolution.y);
  Float phi = 2 * kPi * pRaster.x / Float(options_.fullResolution.x);
  Float sinTheta = std::sin(theta);
  return Vector3f(sinTheta * std::cos(phi), std::cos(theta), sinTheta * std::sin(phi));
}

Ray EnvironmentCamera::worldRay(const Transform& cameraToWorld, const Point2f& pRaster,
                                Float time) const {
  Vector3f d = cameraToWorld(cameraDirection(pRaster));
  // cameraToWorld may scale: distances along the ray are in camera units, so the clipping
  // radii scale with the direction's length before it is normalized.
  Float len = d.length();
  Point3f origin = cameraToWorld(Point3f(0, 0, 0));
  Vector3f dir = d / len;
  return Ray(origin + dir * (options_.hither * len), dir, (options_.yon - options_.hither) * len,
             time);
}

RayDifferential EnvironmentCamera::worldRayDifferential(const Transform& cameraToWorld,
                                                        const Point2f& pRaster, Float time) const {
  // The offset rays at the same instant, under the same transform as the main ray.
  return RayDifferential(worldRay(cameraToWorld, pRaster, time),
                         worldRay(cameraToWorld, Point2f(pRaster.x + 1, pRaster.y), time),
                         worldRay(cameraToWorld, Point2f(pRaster.x, pRaster.y + 1), time));
}

// As for the projective cameras: the transform at the ray's time (pbrt 2e §6.1), a still camera's
// one transform used in place rather than copied by interpolate() for every ray.
Float EnvironmentCamera::generateRay(const CameraSample& sample, Ray* ray) const {
  Float time = lerp(sample.time, options_.shutterOpen, options_.shutterClose);
  *ray = cameraToWorld_.withTransformAt(
      time, [&](const Transform& transform) { return worldRay(transform, sample.pFilm, time); });
  return 1;
}

Float EnvironmentCamera::generateRayDifferential(const CameraSample& sample,
                                                 RayDifferential* ray) const {
  Float time = lerp(sample.time, options_.shutterOpen, options_.shutterClose);
  *ray = cameraToWorld_.withTransformAt(time, [&](const Transform& transform) {
    return worldRayDifferential(transform, sample.pFilm, time);
  });
  return 1;
}

}  // namespace candela
