// Accelerator name -> Aggregate, through the accelerators' table (accel/accelerator_plugins.h):
// Embree (candela's default) or one of the books' reference aggregates. Only the selected one is
// built (DESIGN.md, data flow step 2).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "accel/aggregate.h"
#include "accel/scene_geometry.h"
#include "core/paramset.h"

namespace candela {

class EmbreeDevice;

// The table's names (accel/accelerator_plugins.h), default first.
const std::vector<std::string>& acceleratorNames();
bool isAcceleratorName(const std::string& name);

// Creates the aggregate called name ("" = "embree") with the Accelerator statement's params, as
// its table entry declares them (`candela --describe accelerator/NAME` lists them). The geometry
// (and the device) must outlive the aggregate. Throws SceneError at loc (with no location when
// loc names no file) for an unknown name (the message lists the table's names), or at the
// parameter for a bad value.
std::unique_ptr<Aggregate> createAggregate(const std::string& name, const ParamSet& params,
                                           const SceneGeometry& geometry,
                                           const EmbreeDevice& device, const FileLoc& loc);
// The same over static world-space primitives only.
std::unique_ptr<Aggregate> createAggregate(const std::string& name, const ParamSet& params,
                                           const std::vector<Primitive>& primitives,
                                           const EmbreeDevice& device, const FileLoc& loc);

}  // namespace candela
