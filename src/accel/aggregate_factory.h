// Accelerator name -> Aggregate: "embree" (candela's default), and the reference aggregates
// "bvh" (pbrt-v2's default), "kdtree" and "grid" (the lrt draft's, §4.3-4.4). Only the selected
// one is built (DESIGN.md, data flow step 2).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "accel/aggregate.h"
#include "accel/scene_geometry.h"
#include "core/paramset.h"

namespace candela {

class EmbreeDevice;

// The accepted names, default first.
const std::vector<std::string>& acceleratorNames();
bool isAcceleratorName(const std::string& name);

// Creates the aggregate called name ("" = "embree") with the Accelerator statement's params:
//   kdtree: "integer intersectcost" 80, "integer traversalcost" 1, "float emptybonus" 0.2 (the
//           draft's App. C types it "integer"; both are read), "integer maxprims" 1,
//           "integer maxdepth" -1 (<= 0: round(8 + 1.3 log2 N));
//   grid:   "bool refineimmediately" (or the draft's integer): accepted, no effect (see
//           grid/grid_aggregate.h);
//   bvh:    "integer maxnodeprims" 4, "string splitmethod" "sah" | "middle" | "equal" (pbrt-v3's
//           "hlbvh" builds "sah").
// The geometry (and the device) must outlive the aggregate. Throws SceneError at loc for an
// unknown name (the message lists the names) or a bad parameter value.
std::unique_ptr<Aggregate> createAggregate(const std::string& name, const ParamSet& params,
                                           const SceneGeometry& geometry,
                                           const EmbreeDevice& device, const FileLoc& loc);
// The same over static world-space primitives only.
std::unique_ptr<Aggregate> createAggregate(const std::string& name, const ParamSet& params,
                                           const std::vector<Primitive>& primitives,
                                           const EmbreeDevice& device, const FileLoc& loc);

}  // namespace candela
