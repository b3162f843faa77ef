#include "cameras/camera_plugins.h"

#include <cmath>

#include "cameras/environment_camera.h"
#include "cameras/lens_file.h"
#include "cameras/orthographic_camera.h"
#include "cameras/perspective_camera.h"
#include "cameras/realistic_camera.h"
#include "core/scene_path.h"

namespace candela {

namespace {

std::string str(Float v) { return std::to_string(v); }

// The shutter interval and the clipping distances, common to every camera but the realistic one.
void readShutterAndClipping(const ParamSet& params, const FileLoc& loc, Float* shutterOpen,
                            Float* shutterClose, Float* hither, Float* yon) {
  *shutterOpen = params.getOneFloat("shutteropen", 0);
  *shutterClose = params.getOneFloat("shutterclose", 1);
  // pbrt-v2 swaps a reversed shutter interval rather than rejecting it.
  if (*shutterClose < *shutterOpen) std::swap(*shutterOpen, *shutterClose);

  // Rays start at the camera (hither 0) unless the scene asks for clipping, as in pbrt-v2 and
  // pbrt-v3: the lrt draft's absolute default of 1e-3 clipped away a whole scene 1e-4 in size.
  *hither = params.getOneFloat("hither", 0, ValueRange::nonNegative(), loc);
  *yon = params.getOneFloat("yon", 1e30f);
  if (!(*yon > *hither))
    throw SceneError(params.locationOf("hither", loc),
                     "clipping planes need 0 <= hither < yon, got hither " + str(*hither) +
                         ", yon " + str(*yon));
}

ProjectiveCameraOptions projectiveOptions(const ParamSet& params, const Point2i& resolution,
                                          const FileLoc& loc) {
  ProjectiveCameraOptions o;
  o.fullResolution = resolution;
  auto where = [&](const char* name) { return params.locationOf(name, loc); };

  Float frame = params.getOneFloat("frameaspectratio", Float(resolution.x) / Float(resolution.y),
                                   ValueRange::positive(), loc);
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

  o.lensRadius = params.getOneFloat("lensradius", 0, ValueRange::nonNegative(), loc);
  // An infinite focal distance (focus at infinity) is allowed.
  o.focalDistance = params.getOneFloat("focaldistance", 1e30f, ValueRange::greaterThan(0), loc);

  readShutterAndClipping(params, loc, &o.shutterOpen, &o.shutterClose, &o.hither, &o.yon);
  return o;
}

std::unique_ptr<Camera> createPerspectiveCamera(const ParamSet& params,
                                                const AnimatedTransform& cameraToWorld,
                                                const Point2i& resolution, Float /*filmDiagonal*/,
                                                const FileLoc& loc) {
  PerspectiveCameraOptions o;
  static_cast<ProjectiveCameraOptions&>(o) = projectiveOptions(params, resolution, loc);
  // pbrt-v2 also reads "halffov" (half the angle), which wins when positive; then "fov" is not
  // checked, and a halffov of 0 or less means none.
  o.fov = params.getOneFloat("fov", 90);
  Float halfFov = params.getOneFloat("halffov", -1);
  if (halfFov > 0) {
    params.requireInRange("halffov", halfFov, ValueRange::between(0, 90), loc);
    o.fov = 2 * halfFov;
  } else {
    params.requireInRange("fov", o.fov, ValueRange::between(0, 180), loc);
  }
  return std::make_unique<PerspectiveCamera>(cameraToWorld, o);
}

std::unique_ptr<Camera> createOrthographicCamera(const ParamSet& params,
                                                 const AnimatedTransform& cameraToWorld,
                                                 const Point2i& resolution, Float /*filmDiagonal*/,
                                                 const FileLoc& loc) {
  return std::make_unique<OrthographicCamera>(cameraToWorld,
                                              projectiveOptions(params, resolution, loc));
}

std::unique_ptr<Camera> createEnvironmentCamera(const ParamSet& params,
                                                const AnimatedTransform& cameraToWorld,
                                                const Point2i& resolution, Float /*filmDiagonal*/,
                                                const FileLoc& loc) {
  EnvironmentCameraOptions o;
  o.fullResolution = resolution;
  readShutterAndClipping(params, loc, &o.shutterOpen, &o.shutterClose, &o.hither, &o.yon);
  return std::make_unique<EnvironmentCamera>(cameraToWorld, o);
}

// pbrt-v3's "realistic" camera: the lens file is read relative to the scene file naming it.
std::unique_ptr<Camera> createRealisticCamera(const ParamSet& params,
                                              const AnimatedTransform& cameraToWorld,
                                              const Point2i& resolution, Float filmDiagonal,
                                              const FileLoc& loc) {
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
  Float aperture = params.getOneFloat("aperturediameter", 1, ValueRange::positive(), loc);
  o.apertureDiameter = double(aperture) * 1e-3;
  o.focusDistance = params.getOneFloat("focusdistance", 10, ValueRange::positive(), loc);
  o.simpleWeighting = params.getOneBool("simpleweighting", true);
  // The Film's parameter, checked there too; a camera made without a film may still pass 0.
  if (!(filmDiagonal > 0) || !std::isfinite(filmDiagonal))
    throw SceneError(loc,
                     "the film's \"diagonal\" must be positive (mm), got " + str(filmDiagonal));
  o.filmDiagonal = double(filmDiagonal) * 1e-3;
  o.shutterOpen = params.getOneFloat("shutteropen", 0);
  o.shutterClose = params.getOneFloat("shutterclose", 1);
  if (o.shutterClose < o.shutterOpen) std::swap(o.shutterOpen, o.shutterClose);
  try {
    return std::make_unique<RealisticCamera>(cameraToWorld, o);
  } catch (const std::runtime_error& e) {
    throw SceneError(params.locationOf("focusdistance", params.locationOf("lensfile", loc)),
                     "camera \"realistic\" cannot focus at \"focusdistance\" " +
                         str(Float(o.focusDistance)) + " m: " + e.what());
  }
}

// Every camera's shutter and clipping.
constexpr std::array<ParamSpec, 4> kShutterAndClipping = {{
    {"shutteropen", "float", "0", "", "", kAllDialects, "shutter open time"},
    {"shutterclose", "float", "1", "", "", kAllDialects,
     "shutter close time (a reversed interval is swapped)"},
    {"hither", "float", "0", "", "non-negative and finite", kAllDialects,
     "near clipping distance (below yon)"},
    {"yon", "float", "1e30", "", "", kAllDialects, "far clipping distance (above hither)"},
}};

// The projective cameras' parameters, as projectiveOptions reads them; perspective adds its field
// of view.
constexpr auto kOrthographicParams = joinParams(
    kShutterAndClipping,
    std::to_array<ParamSpec>({
        {"frameaspectratio", "float", "(the image's width / height)", "", "positive and finite",
         kAllDialects, "width / height of the default screen window"},
        {"screenwindow", "float[]", "(from frameaspectratio)", "", "", kAllDialects,
         "xmin xmax ymin ymax on the image plane"},
        {"lensradius", "float", "0", "", "non-negative and finite", kAllDialects,
         "thin lens radius; 0 is a pinhole"},
        {"focaldistance", "float", "1e30", "", "greater than 0", kAllDialects,
         "distance of the plane in focus"},
    }));

constexpr auto kPerspectiveParams =
    joinParams(kOrthographicParams,
               std::to_array<ParamSpec>({
                   {"fov", "float", "90", "", "within (0, 180)", kAllDialects,
                    "field of view along the shorter image axis, degrees"},
                   {"halffov", "float", "-1", "", "", kAllDialects,
                    "half the field of view; when positive it wins over fov and must be below 90"},
               }));

constexpr auto kEnvironmentParams = kShutterAndClipping;

constexpr ParamSpec kRealisticParams[] = {
    {"lensfile", "string", "(required)", "", "", kPbrtV3,
     "lens prescription, relative to the scene file"},
    {"aperturediameter", "float", "1", "", "positive and finite", kPbrtV3,
     "aperture stop diameter, mm"},
    {"focusdistance", "float", "10", "", "positive and finite", kPbrtV3, "distance in focus, m"},
    {"simpleweighting", "bool", "true", "", "", kPbrtV3,
     "weight rays by cos^4 only, not the exit pupil's area"},
    {"shutteropen", "float", "0", "", "", kPbrtV3, "shutter open time"},
    {"shutterclose", "float", "1", "", "", kPbrtV3,
     "shutter close time (a reversed interval is swapped)"},
};

const CameraPlugin kCameras[] = {
    {{"camera", "perspective", kAllDialects,
      "pinhole or thin-lens perspective projection (lrt draft §6.2)", kPerspectiveParams},
     createPerspectiveCamera},
    {{"camera", "orthographic", kAllDialects,
      "orthographic projection, optionally with a thin lens (lrt draft §6.2.1)",
      kOrthographicParams},
     createOrthographicCamera},
    {{"camera", "environment", kAllDialects,
      "latitude-longitude view of every direction (lrt draft §6.3)", kEnvironmentParams},
     createEnvironmentCamera},
    {{"camera", "realistic", kPbrtV3,
      "lens system traced from the film, from a lens file (pbrt 3e §6.4)", kRealisticParams},
     createRealisticCamera},
};

}  // namespace

std::span<const CameraPlugin> cameraPlugins() { return kCameras; }

}  // namespace candela
