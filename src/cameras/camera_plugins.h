// The cameras' table (issue 34: one home per plug-in): each camera's name, dialects, parameters
// and create function. createCamera dispatches through it, and unknown-name errors, `candela
// --list-plugins` and `candela --describe` read it.
#pragma once

#include <memory>
#include <span>

#include "cameras/camera.h"
#include "core/plugin_spec.h"

namespace candela {

// What every camera is made from: its parameters, cameraToWorld over the shutter, the film's full
// resolution (at least 1 x 1, checked by createCamera) and "diagonal" in mm (the realistic
// camera's film size). Bad values are SceneErrors at the parameter, or at loc.
using CameraCreate = std::unique_ptr<Camera> (*)(const ParamSet& params,
                                                 const AnimatedTransform& cameraToWorld,
                                                 const Point2i& fullResolution, Float filmDiagonal,
                                                 const FileLoc& loc);

struct CameraPlugin {
  PluginSpec spec;
  CameraCreate create;
};

std::span<const CameraPlugin> cameraPlugins();

}  // namespace candela
