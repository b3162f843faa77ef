// The accelerators' table (issue 34: one home per plug-in): each accelerator's name, dialects,
// parameters and create function. createAggregate (accel/aggregate_factory.h) dispatches through
// it, and unknown-name errors, --accel's choices, `candela --list-plugins` and `candela
// --describe` read it.
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "accel/aggregate.h"
#include "accel/scene_geometry.h"
#include "core/paramset.h"
#include "core/plugin_spec.h"

namespace candela {

class EmbreeDevice;

// What an aggregate is built over: a scene's geometry (instances included) or static world-space
// primitives alone; exactly one of the two is set. Both, and the device, must outlive it.
struct AcceleratorInput {
  const SceneGeometry* geometry;
  const std::vector<Primitive>* primitives;
  const EmbreeDevice& device;
};

// The aggregate with the Accelerator statement's parameters. Bad values are SceneErrors at the
// parameter, or at loc.
using AcceleratorCreate = std::unique_ptr<Aggregate> (*)(const AcceleratorInput& in,
                                                         const ParamSet& params,
                                                         const FileLoc& loc);

struct AcceleratorPlugin {
  PluginSpec spec;
  AcceleratorCreate create;
};

// The default ("embree") first.
std::span<const AcceleratorPlugin> acceleratorPlugins();

}  // namespace candela
