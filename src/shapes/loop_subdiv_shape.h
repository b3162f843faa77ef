// The "loopsubdiv" shape (lrt draft §3.7; appendix C calls it "subdiv"): a control triangle mesh
// refined once, at scene build, into a TriangleMesh whose vertices are on the limit surface.
#pragma once

#include <memory>
#include <vector>

#include "shapes/triangle_mesh.h"

namespace candela {

// Which code refines: ours with the draft's rules (LoopRules{Warren, Book}), or OpenSubdiv 3.5
// (VTX_BOUNDARY_EDGE_ONLY, i.e. ours with LoopRules{Loop, BSpline}).
enum class LoopProducer { Book, OpenSubdiv };

// "nlevels" (integer, default 3, 0 to 8), "indices" (3 per triangle), "P" (point3); optional "uv"
// (or "st") and "N", one per control vertex. uv and N are carried through linearly (each refined
// vertex gets the control face's barycentric interpolation of them), since the draft defines no
// smooth rule for them; N, when given, is used (normalized) instead of the limit normals. The
// refined vertices are moved to their limit positions. Bad parameters or topology: SceneError at
// loc naming "loopsubdiv" and, for topology, the face.
std::vector<std::unique_ptr<Shape>> createLoopSubdivShapes(
    const Transform& objectToWorld, bool reverseOrientation, const ParamSet& params,
    std::unique_ptr<TriangleMesh>* meshOut, const FileLoc& loc,
    LoopProducer producer = LoopProducer::Book);

}  // namespace candela
