// Cameras (lrt draft ch. 6): turn a CameraSample into a world-space ray. pbrt's conventions:
// left-handed camera space looking down +z, fov along the shorter image axis.
#pragma once

#include <memory>
#include <string>

#include "core/animated_transform.h"
#include "core/bounds.h"
#include "core/interaction.h"
#include "core/paramset.h"
#include "core/spectrum.h"
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
  // Whether the rays depend on CameraSample::pLens (a pinhole's do not: the renderer then lets the
  // sampler pass over the lens dimensions without computing them).
  virtual bool readsLensSample() const { return true; }
  // The times the camera's rays span (prepasses such as photon shooting sample the same).
  virtual Float shutterOpen() const { return 0; }
  virtual Float shutterClose() const { return 0; }

  // Camera importance (pbrt 3e §16.1.1), for integrators that connect light paths to the camera.
  // A camera without it answers null and a caller that needs it reports the camera unsupported.
  virtual const class CameraImportance* importance() const { return nullptr; }
  // The name the scene gave the camera ("perspective"), for such messages.
  virtual const char* kind() const = 0;
  // Whether the clipping planes (hither, yon) leave out every point of `world` at both ends of
  // the shutter: the image can only be empty, which deserves a warning.
  virtual bool clipsAway(const Bounds3f& world) const {
    (void)world;
    return false;
  }
};

// What sampleWi returns: a point on the lens seen from a reference point.
struct CameraWiSample {
  Spectrum We;        // importance along the ray from the lens point toward ref
  Vector3f wi;        // unit, from ref toward the lens point
  Float pdf = 0;      // solid-angle density at ref
  Point2f pRaster;    // where the ray lands on the film
  Interaction pLens;  // the lens point (its normal is the viewing axis), for the shadow ray
};

class CameraImportance {
 public:
  virtual ~CameraImportance() = default;
  // Importance of a ray leaving the lens (its origin may be anywhere on the camera ray) and the
  // raster position it maps to; 0 outside the film.
  virtual Spectrum We(const Ray& ray, Point2f* pRaster) const = 0;
  // Densities of generating the ray: per area of the lens and per solid angle (0 off the film).
  virtual void pdfWe(const Ray& ray, Float* pdfPos, Float* pdfDir) const = 0;
  // A lens point as seen from ref; pdf is 0 when none can see it.
  virtual CameraWiSample sampleWi(const Interaction& ref, const Point2f& u) const = 0;
  // The lens point a camera ray left from (rays start at the near plane).
  virtual Point3f lensPoint(const Ray& ray) const = 0;
  // The viewing axis (the lens normal) at a time.
  virtual Vector3f axis(Float time) const = 0;
};

// The camera named by a Camera statement ("perspective", "orthographic" or "environment"), with
// pbrt-v2's parameters and defaults, or pbrt-v3's "realistic"; cameraToWorld is the inverse of
// the CTM at the statement at the two transform times, fullResolution the film's, filmDiagonal
// the film's "diagonal" in millimetres (only the realistic camera uses it; pbrt-v3's default 35).
// A moving camera takes each ray to world space by the transform at the ray's time (pbrt 2e
// §6.1). An unknown name or a bad value is a SceneError at loc (or at the parameter).
std::unique_ptr<Camera> createCamera(const std::string& name, const ParamSet& params,
                                     const AnimatedTransform& cameraToWorld,
                                     const Point2i& fullResolution, const FileLoc& loc,
                                     Float filmDiagonal = 35);
// A camera that stands still.
std::unique_ptr<Camera> createCamera(const std::string& name, const ParamSet& params,
                                     const Transform& cameraToWorld, const Point2i& fullResolution,
                                     const FileLoc& loc, Float filmDiagonal = 35);

}  // namespace candela
