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
  LoopMesh refined;              // the last level, in OpenSubdiv's vertex numbering and faces
  std::vector<Point3f> limitP;   // the limit of each refined vertex
  std::vector<Normal3f> limitN;  // unit, turned to the side the incident faces wind towards
  // For each vertex of refineLoop's result at the same level (even vertices first, then one per
  // edge in buildLoopTopology's order), its index in refined.
  std::vector<int> fromOurs;
};

// Validates control as refineLoop does (SceneError naming shapeName and the face) before handing
// it to OpenSubdiv, which must never see bad topology.
OsdLoopResult refineLoopOpenSubdiv(const LoopMesh& control, int levels, OsdBoundary boundary,
                                   const FileLoc& loc = {},
                                   const std::string& shapeName = "loopsubdiv");

}  // namespace candela
