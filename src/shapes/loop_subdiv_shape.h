// The "loopsubdiv" shape (lrt draft §3.7; appendix C calls it "subdiv"): a control triangle mesh
// refined once, at scene build, into a TriangleMesh whose vertices are on the limit surface.
#pragma once

#include <memory>
#include <vector>

#include "core/compatibility.h"
#include "shapes/loop_subdiv.h"
#include "shapes/triangle_mesh.h"

namespace candela {

// The rules the shape uses with either producer: Loop's β and the B-spline boundary limit, which
// are what OpenSubdiv implements. The draft's 1/5, 3/5, 1/5 boundary limit puts the point off the
// boundary curve (a defect); its β (Warren's 3/(8n)) is a legitimate variant, kept in LoopRules and
// tested, but OpenSubdiv has no option for it, and both producers must agree.
inline constexpr LoopRules kLoopSubdivShapeRules{LoopRules::Loop, LoopRules::BSpline};

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
