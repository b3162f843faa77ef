// The shapes' table (issue 34: one home per plug-in): each shape's name, dialects, parameters and
// create function. createShapes (assembly/shape_factory.h) dispatches through it, and
// unknown-name errors, `candela --list-plugins` and `candela --describe` read it.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/compatibility.h"
#include "core/paramset.h"
#include "core/plugin_spec.h"
#include "core/transform.h"
#include "shapes/shape.h"

namespace candela {

struct TriangleMesh;

// What a Shape statement gives every shape: its parameters and placement, where it was written
// (errors about absent parameters name it), the scene file's directory (relative file names are
// relative to it: "plymesh") and the options that choose between codes for the same surface.
struct ShapeInputs {
  const Transform& objectToWorld;
  bool reverseOrientation;
  const ParamSet& params;
  const FileLoc& loc;
  const std::string& directory;
  LoopProducer subdiv;
  HyperboloidNormal hyperboloidNormal;
};

// The shapes of one statement. Meshes (all but the quadrics and curves) also hand over the mesh
// their triangles refer to in *meshOut; the others leave it alone. Bad values are SceneErrors at
// the parameter, or at in.loc.
using ShapeCreate = std::vector<std::unique_ptr<Shape>> (*)(const ShapeInputs& in,
                                                            std::unique_ptr<TriangleMesh>* meshOut);

struct ShapePlugin {
  PluginSpec spec;
  ShapeCreate create;
};

std::span<const ShapePlugin> shapePlugins();

}  // namespace candela
