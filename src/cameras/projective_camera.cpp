#include "cameras/projective_camera.h"

#include "core/sampling.h"

namespace candela {

Bounds2f defaultScreenWindow(Float frameAspectRatio) {
  if (frameAspectRatio > 1)
    return Bounds2f(Point2f(-frameAspectRatio, -1), Point2f(frameAspectRatio, 1));
  return Bounds2f(Point2f(-1, -1 / frameAspectRatio), Point2f(1, 1 / frameAspectRatio));
}

ProjectiveCamera::ProjectiveCamera(const AnimatedTransform& cameraToWorld,
                                   const ProjectiveCameraOptions& options, Float originScale,
                                   Float directionScale)
    : cameraToWorld_(cameraToWorld), options_(options) {
  if (!cameraToWorld_.isAnimated()) worldToCameraStill_ = inverse(cameraToWorld_.interpolate(0));
  // Screen to raster flips y so that raster y grows downwards (lrt draft §6.1). The composition
  // raster -> screen -> pinhole ray is affine, so it is computed directly rather than through
  // the 4x4 projective matrix, which loses precision for a far yon.
  const Bounds2f& sw = options.screenWindow;
  Float xres = Float(options.fullResolution.x), yres = Float(options.fullResolution.y);
  Float dxScreen = (sw.pMax.x - sw.pMin.x) / xres, dyScreen = (sw.pMax.y - sw.pMin.y) / yres;
  o0_ = Point3f(sw.pMin.x * originScale, sw.pMax.y * originScale, 0);
  oDx_ = Vector3f(dxScreen * originScale, 0, 0);
  oDy_ = Vector3f(0, -dyScreen * originScale, 0);
  d0_ = Vector3f(sw.pMin.x * directionScale, sw.pMax.y * directionScale, 1);
  dDx_ = Vector3f(dxScreen * directionScale, 0, 0);
  dDy_ = Vector3f(0, -dyScreen * directionScale, 0);
}

void ProjectiveCamera::transformsAt(Float time, Transform* cameraToWorld,
                                    Transform* worldToCamera) const {
  *cameraToWorld = cameraToWorld_.interpolate(time);
  *worldToCamera = cameraToWorld_.isAnimated() ? inverse(*cameraToWorld) : worldToCameraStill_;
}

bool ProjectiveCamera::clipsAway(const Bounds3f& world) const {
  if (world.empty()) return false;
  for (Float time : {options_.shutterOpen, options_.shutterClose}) {
    Transform cameraToWorld, worldToCamera;
    transformsAt(time, &cameraToWorld, &worldToCamera);
    // The box is convex: its camera-space z range is that of its corners.
    Float zMin = kInfinity, zMax = -kInfinity;
    for (int c = 0; c < 8; ++c) {
      Float z = worldToCamera(world.corner(c)).z;
      zMin = std::min(zMin, z);
      zMax = std::max(zMax, z);
    }
    if (!(zMax < options_.hither || zMin > options_.yon)) return false;
  }
  return true;
}

Point2f ProjectiveCamera::rasterToScreen(const Point2f& pRaster) const {
  const Bounds2f& sw = options_.screenWindow;
  Float xres = Float(options_.fullResolution.x), yres = Float(options_.fullResolution.y);
  return Point2f(sw.pMin.x + pRaster.x * ((sw.pMax.x - sw.pMin.x) / xres),
                 sw.pMax.y - pRaster.y * ((sw.pMax.y - sw.pMin.y) / yres));
}

// The steps of every camera ray, inline: a call cost as much as each one's arithmetic.
inline void ProjectiveCamera::pinholeRay(const Point2f& pRaster, Point3f* o, Vector3f* d) const {
  *o = Point3f(o0_.x + pRaster.x * oDx_.x, o0_.y + pRaster.y * oDy_.y, 0);
  *d = Vector3f(d0_.x + pRaster.x * dDx_.x, d0_.y + pRaster.y * dDy_.y, 1);
}

inline void ProjectiveCamera::lensRay(Point3f o, Vector3f d, const Point2f& uLens, Point3f* origin,
                                      Vector3f* dir, Float* tMax) const {
  if (options_.lensRadius > 0) {
    // Thin lens (lrt draft §6.2.3): every ray from the film point through the lens meets the
    // pinhole ray on the plane of focus z = focalDistance (d.z = 1, so t = focalDistance). The
    // lens is centred on the pinhole ray's origin: for the orthographic camera that is the film
    // point, not the camera's origin as in pbrt-v2/v3, whose rays all leave from a lens around
    // the optical axis and so blur wrongly off-axis (pbrt-v3 issue #315).
    Point2f pLens = sampleUniformDiskConcentric(uLens) * options_.lensRadius;
    Point3f pFocus = o + d * options_.focalDistance;
    o = Point3f(o.x + pLens.x, o.y + pLens.y, 0);
    d = pFocus - o;
  }
  d = normalize(d);
  // Start at the hither plane and stop at the yon plane (lrt draft §6.1: clipping planes).
  *origin = o + d * (options_.hither / d.z);
  *dir = d;
  *tMax = (options_.yon - options_.hither) / d.z;
}

inline Ray ProjectiveCamera::toWorld(const Transform& cameraToWorld, const Point3f& o,
                                     const Vector3f& d, Float tMax, Float time) {
  Vector3f dw = cameraToWorld(d);
  Float len = dw.length();
  return Ray(cameraToWorld(o), dw / len, tMax * len, time);
}

Ray ProjectiveCamera::cameraRay(const CameraSample& sample, Float time,
                                const Transform& cameraToWorld) const {
  Point3f o, origin;
  Vector3f d, dir;
  Float tMax;
  pinholeRay(sample.pFilm, &o, &d);
  lensRay(o, d, sample.pLens, &origin, &dir, &tMax);
  return toWorld(cameraToWorld, origin, dir, tMax, time);
}

RayDifferential ProjectiveCamera::cameraRayDifferential(const CameraSample& sample, Float time,
                                                        const Transform& cameraToWorld) const {
  Point3f o, origin;
  Vector3f d, dir;
  Float tMax, unused;
  pinholeRay(sample.pFilm, &o, &d);
  lensRay(o, d, sample.pLens, &origin, &dir, &tMax);
  Ray main = toWorld(cameraToWorld, origin, dir, tMax, time);
  // One pixel over moves the pinhole ray by the affine map's x and y steps. The offset rays are
  // taken to world space by the same transform as the main ray: differentials describe the
  // footprint at one instant, not the camera's motion.
  lensRay(o + oDx_, d + dDx_, sample.pLens, &origin, &dir, &unused);
  Ray rx = toWorld(cameraToWorld, origin, dir, kInfinity, time);
  lensRay(o + oDy_, d + dDy_, sample.pLens, &origin, &dir, &unused);
  Ray ry = toWorld(cameraToWorld, origin, dir, kInfinity, time);
  return RayDifferential(main, rx, ry);
}

// A moving camera takes the ray to world space by the transform at the ray's time (pbrt 2e §6.1).
// A still one has one transform, used in place: interpolate() would return a copy of it for every
// ray.
Float ProjectiveCamera::generateRay(const CameraSample& sample, Ray* ray) const {
  Float time = lerp(sample.time, options_.shutterOpen, options_.shutterClose);
  *ray = cameraToWorld_.withTransformAt(
      time, [&](const Transform& transform) { return cameraRay(sample, time, transform); });
  return 1;
}

Float ProjectiveCamera::generateRayDifferential(const CameraSample& sample,
                                                RayDifferential* ray) const {
  Float time = lerp(sample.time, options_.shutterOpen, options_.shutterClose);
  *ray = cameraToWorld_.withTransformAt(time, [&](const Transform& transform) {
    return cameraRayDifferential(sample, time, transform);
  });
  return 1;
}

}  // namespace candela
