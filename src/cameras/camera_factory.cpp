// Camera "name" -> Camera, with pbrt-v2's parameter names and defaults (lrt draft App. C).
#include <cmath>

#include "cameras/camera.h"
#include "cameras/environment_camera.h"
#include "cameras/orthographic_camera.h"
#include "cameras/perspective_camera.h"

namespace candela {

namespace {

std::string str(Float v) { return std::to_string(v); }

// The shutter interval and the clipping distances, common to every camera.
void readShutterAndClipping(const ParamSet& params, const FileLoc& loc, Float* shutterOpen,
                            Float* shutterClose, Float* hither, Float* yon) {
  *shutterOpen = params.getOneFloat("shutteropen", 0);
  *shutterClose = params.getOneFloat("shutterclose", 1);
  // pbrt-v2 swaps a reversed shutter interval rather than rejecting it.
  if (*shutterClose < *shutterOpen) std::swap(*shutterOpen, *shutterClose);

  *hither = params.getOneFloat("hither", 1e-3f);
  *yon = params.getOneFloat("yon", 1e30f);
  if (!(*hither >= 0) || !(*yon > *hither))
    throw SceneError(params.locationOf("hither", loc),
                     "clipping planes need 0 <= hither < yon, got hither " + str(*hither) +
                         ", yon " + str(*yon));
}

ProjectiveCameraOptions projectiveOptions(const ParamSet& params, const Point2i& resolution,
                                          const FileLoc& loc) {
  ProjectiveCameraOptions o;
  o.fullResolution = resolution;
  auto where = [&](const char* name) { return params.locationOf(name, loc); };

  Float frame = params.getOneFloat("frameaspectratio", Float(resolution.x) / Float(resolution.y));
  if (!(frame > 0) || !std::isfinite(frame))
    throw SceneError(where("frameaspectratio"), "\"frameaspectratio\" must be positive");
  o.screenWindow = defaultScreenWindow(frame);
  std::vector<Float> sw = params.getFloatArray("screenwindow");
  if (!sw.empty()) {
    if (sw.size() != 4)
      throw SceneError(where("screenwindow"),
                       "\"screenwindow\" needs 4 values (xmin xmax ymin ymax), got " +
                           std::to_string(sw.size()));
    if (sw[0] == sw[1] || sw[2] == sw[3] || !std::isfinite(sw[0] + sw[1] + sw[2] + sw[3]))
      throw SceneError(where("screenwindow"), "\"screenwindow\" has zero or infinite extent");
    o.screenWindow = Bounds2f(Point2f(sw[0], sw[2]), Point2f(sw[1], sw[3]));
  }

  o.lensRadius = params.getOneFloat("lensradius", 0);
  if (!(o.lensRadius >= 0) || !std::isfinite(o.lensRadius))
    throw SceneError(where("lensradius"), "\"lensradius\" must be >= 0, got " + str(o.lensRadius));
  o.focalDistance = params.getOneFloat("focaldistance", 1e30f);
  if (!(o.focalDistance > 0))
    throw SceneError(where("focaldistance"),
                     "\"focaldistance\" must be positive, got " + str(o.focalDistance));

  readShutterAndClipping(params, loc, &o.shutterOpen, &o.shutterClose, &o.hither, &o.yon);
  return o;
}

PerspectiveCameraOptions perspectiveOptions(const ParamSet& params, const Point2i& resolution,
                                            const FileLoc& loc) {
  PerspectiveCameraOptions o;
  static_cast<ProjectiveCameraOptions&>(o) = projectiveOptions(params, resolution, loc);
  // pbrt-v2 also reads "halffov" (half the angle), which wins when given.
  o.fov = params.getOneFloat("fov", 90);
  const char* fovName = "fov";
  Float halfFov = params.getOneFloat("halffov", -1);
  if (halfFov > 0) {
    o.fov = 2 * halfFov;
    fovName = "halffov";
  }
  if (!(o.fov > 0 && o.fov < 180))
    throw SceneError(params.locationOf(fovName, loc),
                     "field of view must be between 0 and 180 degrees, got " + str(o.fov));
  return o;
}

EnvironmentCameraOptions environmentOptions(const ParamSet& params, const Point2i& resolution,
                                            const FileLoc& loc) {
  EnvironmentCameraOptions o;
  o.fullResolution = resolution;
  readShutterAndClipping(params, loc, &o.shutterOpen, &o.shutterClose, &o.hither, &o.yon);
  return o;
}

}  // namespace

std::unique_ptr<Camera> createCamera(const std::string& name, const ParamSet& params,
                                     const AnimatedTransform& cameraToWorld,
                                     const Point2i& fullResolution, const FileLoc& loc) {
  if (fullResolution.x < 1 || fullResolution.y < 1)
    throw SceneError(loc, "camera: image resolution must be positive");
  if (name == "perspective")
    return std::make_unique<PerspectiveCamera>(cameraToWorld,
                                               perspectiveOptions(params, fullResolution, loc));
  if (name == "orthographic")
    return std::make_unique<OrthographicCamera>(cameraToWorld,
                                                projectiveOptions(params, fullResolution, loc));
  if (name == "environment")
    return std::make_unique<EnvironmentCamera>(cameraToWorld,
                                               environmentOptions(params, fullResolution, loc));
  throw SceneError(
      loc, "unknown camera \"" + name + "\" (known: perspective, orthographic, environment)");
}

std::unique_ptr<Camera> createCamera(const std::string& name, const ParamSet& params,
                                     const Transform& cameraToWorld, const Point2i& fullResolution,
                                     const FileLoc& loc) {
  return createCamera(name, params, AnimatedTransform(cameraToWorld), fullResolution, loc);
}

}  // namespace candela
