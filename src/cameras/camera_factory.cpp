// Camera "name" -> Camera through the cameras' table (cameras/camera_plugins.cpp: pbrt-v2's
// parameter names and defaults, lrt draft App. C, and pbrt-v3's "realistic" camera, pbrt 3e
// §6.4), then the checks every camera shares.
#include <cmath>

#include "cameras/camera.h"
#include "cameras/camera_plugins.h"

namespace candela {

namespace {

std::string str(Float v) { return std::to_string(v); }

// Parameters and transforms that are each finite can still make rays that are not (a screen
// window of +-1e38, a camera moved by 1e38 at the end of the shutter). Rays through the corners,
// edge midpoints and centre of the film, at the shutter's open, middle and close, from the lens
// centre, must be traceable.
void checkRaysTraceable(const Camera& camera, const Point2i& resolution, const FileLoc& loc) {
  // CameraSample::time is in [0, 1), mapped onto the shutter by the camera.
  for (Float time : {Float(0), Float(0.5), kOneMinusEpsilon})
    for (int j = 0; j <= 2; ++j)
      for (int i = 0; i <= 2; ++i) {
        CameraSample cs;
        cs.pFilm = Point2f(Float(resolution.x) * Float(i) / 2, Float(resolution.y) * Float(j) / 2);
        cs.pLens = Point2f(0.5f, 0.5f);
        cs.time = time;
        Ray ray;
        if (camera.generateRay(cs, &ray) <= 0) continue;
        if (!withinTraceableRange(ray.o, ray.d) || std::isnan(ray.tMax))
          throw SceneError(loc, "camera \"" + std::string(camera.kind()) +
                                    "\": its screen window and transforms make rays that start "
                                    "or point beyond 1.8e18 or are not finite (ray at film (" +
                                    str(cs.pFilm.x) + ", " + str(cs.pFilm.y) + "), time " +
                                    str(time) + ")");
      }
}

}  // namespace

std::unique_ptr<Camera> createCamera(const std::string& name, const ParamSet& params,
                                     const AnimatedTransform& cameraToWorld,
                                     const Point2i& fullResolution, const FileLoc& loc,
                                     Float filmDiagonal) {
  if (fullResolution.x < 1 || fullResolution.y < 1)
    throw SceneError(loc, "camera: image resolution must be positive");
  const CameraPlugin& plugin = requirePlugin(cameraPlugins(), "camera", name, loc);
  std::unique_ptr<Camera> camera =
      plugin.create(params, cameraToWorld, fullResolution, filmDiagonal, loc);
  checkRaysTraceable(*camera, fullResolution, loc);
  return camera;
}

std::unique_ptr<Camera> createCamera(const std::string& name, const ParamSet& params,
                                     const Transform& cameraToWorld, const Point2i& fullResolution,
                                     const FileLoc& loc, Float filmDiagonal) {
  return createCamera(name, params, AnimatedTransform(cameraToWorld), fullResolution, loc,
                      filmDiagonal);
}

}  // namespace candela
