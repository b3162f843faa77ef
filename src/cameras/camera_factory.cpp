// Camera "name" -> Camera, with pbrt-v2's parameter names and defaults (lrt draft App. C), and
// pbrt-v3's "realistic" camera (pbrt 3e §6.4).
#include <cmath>

#include "cameras/camera.h"
#include "cameras/environment_camera.h"
#include "cameras/lens_file.h"
#include "cameras/orthographic_camera.h"
#include "cameras/perspective_camera.h"
#include "cameras/realistic_camera.h"
#include "core/scene_path.h"

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

  // Rays start at the camera (hither 0) unless the scene asks for clipping, as in pbrt-v2 and
  // pbrt-v3: the lrt draft's absolute default of 1e-3 clipped away a whole scene 1e-4 in size.
  *hither = params.getOneFloat("hither", 0);
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

// pbrt-v3's "realistic" camera: the lens file is read relative to the scene file naming it.
RealisticCameraOptions realisticOptions(const ParamSet& params, const Point2i& resolution,
                                        Float filmDiagonal, const FileLoc& loc) {
  RealisticCameraOptions o;
  o.fullResolution = resolution;
  auto where = [&](const char* name) { return params.locationOf(name, loc); };
  std::string lensFile = params.getOneString("lensfile", "");
  if (lensFile.empty())
    throw SceneError(where("lensfile"), "camera \"realistic\" needs a \"string lensfile\"");
  std::string path = resolveScenePath(lensFile, where("lensfile").file);
  try {
    o.lens = readLensFile(path);
  } catch (const FileError& e) {
    throw SceneError(where("lensfile"), std::string("cannot read \"lensfile\": ") + e.what());
  }
  // Millimetres in the scene, metres inside (pbrt 3e §6.4.1).
  Float aperture = params.getOneFloat("aperturediameter", 1);
  if (!(aperture > 0) || !std::isfinite(aperture))
    throw SceneError(where("aperturediameter"),
                     "\"aperturediameter\" must be positive (mm), got " + str(aperture));
  o.apertureDiameter = double(aperture) * 1e-3;
  Float focus = params.getOneFloat("focusdistance", 10);
  if (!(focus > 0) || !std::isfinite(focus))
    throw SceneError(where("focusdistance"),
                     "\"focusdistance\" must be positive, got " + str(focus));
  o.focusDistance = focus;
  o.simpleWeighting = params.getOneBool("simpleweighting", true);
  if (!(filmDiagonal > 0) || !std::isfinite(filmDiagonal))
    throw SceneError(loc,
                     "the film's \"diagonal\" must be positive (mm), got " + str(filmDiagonal));
  o.filmDiagonal = double(filmDiagonal) * 1e-3;
  o.shutterOpen = params.getOneFloat("shutteropen", 0);
  o.shutterClose = params.getOneFloat("shutterclose", 1);
  if (o.shutterClose < o.shutterOpen) std::swap(o.shutterOpen, o.shutterClose);
  return o;
}

std::unique_ptr<Camera> createUncheckedCamera(const std::string& name, const ParamSet& params,
                                              const AnimatedTransform& cameraToWorld,
                                              const Point2i& fullResolution, const FileLoc& loc,
                                              Float filmDiagonal) {
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
  if (name == "realistic") {
    RealisticCameraOptions o = realisticOptions(params, fullResolution, filmDiagonal, loc);
    try {
      return std::make_unique<RealisticCamera>(cameraToWorld, o);
    } catch (const std::runtime_error& e) {
      throw SceneError(params.locationOf("focusdistance", params.locationOf("lensfile", loc)),
                       "camera \"realistic\" cannot focus at \"focusdistance\" " +
                           str(Float(o.focusDistance)) + " m: " + e.what());
    }
  }
  throw SceneError(loc, "unknown camera \"" + name +
                            "\" (known: perspective, orthographic, environment, realistic)");
}

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
  std::unique_ptr<Camera> camera =
      createUncheckedCamera(name, params, cameraToWorld, fullResolution, loc, filmDiagonal);
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
