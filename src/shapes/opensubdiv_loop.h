// The same Loop subdivision computed by OpenSubdiv 3.5 (Far::TopologyRefiner, Sdc::SCHEME_LOOP,
// uniform refinement, PrimvarRefiner::Limit), as a second producer and as the reference our own
// code (loop_subdiv.h) is tested against. OpenSubdiv's rules are ours with LoopRules{Loop,
// BSpline}; see loop_subdiv.h for where the draft's differ.
#pragma once

#include <string>
#include <vector>

#include "shapes/loop_subdiv.h"

namespace candela {

// OpenSubdiv's boundary options. EdgeOnly treats boundaries as the draft does (a crease: the cubic
// B-spline rules 3/4, 1/8, 1/8 and 1/2, 1/2). EdgeAndCorner also pins every vertex with a single
// face (a corner) in place at every level and in the limit, which the draft never does.
enum class OsdBoundary { EdgeOnly, EdgeAndCorner };

struct OsdLoopResult {
  LoopMesh refined;               // the last level, in OpenSubdiv's vertex numbering and faces
  std::vector<LoopPoint> limitP;  // the limit of each refined vertex
  std::vector<Normal3f> limitN;   // unit, turned to the side the incident faces wind towards
  // The values passed as `linear`, refined linearly (OpenSubdiv's "varying" interpolation: what
  // refineLinearOnce does), one per refined vertex.
  std::vector<std::vector<LoopPoint>> linear;
};

// Validates control as refineLoop does (SceneError naming shapeName and the face) before handing
// it to OpenSubdiv, which must never see bad topology. Runs in double, like our code. Each entry
// of linear (up to three components per control vertex: uv, user normals) is carried along.
OsdLoopResult refineLoopOpenSubdiv(const LoopMesh& control, int levels, OsdBoundary boundary,
                                   const FileLoc& loc = {},
                                   const std::string& shapeName = "loopsubdiv",
                                   const std::vector<std::vector<LoopPoint>>& linear = {});

// For each vertex of refineLoop(control, levels)'s result (even vertices first, then one per edge
// in buildLoopTopology's order, level by level), the index of the same vertex in
// refineLoopOpenSubdiv's: how the cross-checks pair them up.
std::vector<int> openSubdivIndexOfOurs(const LoopMesh& control, int levels);

}  // namespace candela
