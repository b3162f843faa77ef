// Loop subdivision of triangle meshes (lrt draft §3.7, seed 000 inventory §3 "subdiv"): each level
// splits every triangle in four, moving the old ("even") vertices and placing the new ("odd")
// ones on the edges by fixed masks; the last level's vertices are then pushed to their limit
// positions, with normals from the limit tangents.
//
// Two choices where the draft and OpenSubdiv 3.5 (Sdc::SCHEME_LOOP) differ; everything else (the
// even and odd masks inside and on boundaries, the crease-like boundary rule, the interior limit
// and the tangent masks) is the same in both:
// - β(n), the even-vertex weight of each neighbour of an interior vertex of valence n: the draft
//   uses Warren's 3/(8n) (3/16 at n = 3); OpenSubdiv Loop's original (1/n)(5/8 − (3/8 +
//   cos(2π/n)/4)²). Both give 3/16 at n = 3 and 1/16 at n = 6, so they differ only at the other
//   valences, e.g. β(4) = 3/32 against 31/256, β(5) = 3/40 against 0.08409.
// - The limit of a boundary vertex: the draft weighs (neighbour, vertex, neighbour) by
//   (1/5, 3/5, 1/5); the boundary curve is a cubic B-spline, whose limit mask is (1/6, 2/3, 1/6),
//   which is what OpenSubdiv uses. The draft's point is off the curve by (1/30)(first + last − 2v).
#pragma once

#include <string>
#include <vector>

#include "shapes/loop_subdiv_topology.h"

namespace candela {

struct LoopRules {
  enum Beta { Warren, Loop };
  enum BoundaryLimit { Book, BSpline };
  Beta beta = Warren;
  BoundaryLimit boundaryLimit = Book;
};

// β(n) of the even-vertex rule for an interior vertex of valence n.
double loopBeta(int valence, LoopRules::Beta beta);
// The weight of each neighbour in the interior limit mask: γ(n) = 1 / (n + 3 / (8 β(n))).
double loopLimitGamma(int valence, LoopRules::Beta beta);

// One level: vertex i of the result is the even vertex for mesh vertex i; vertex nv + e the odd
// vertex on topology edge e. Face f becomes faces 4f..4f+3 (one per corner, then the middle), all
// wound as f was.
LoopMesh refineLoopOnce(const LoopMesh& mesh, const LoopTopology& topology, const LoopRules& rules);

// levels applications of refineLoopOnce, after validating control (see buildLoopTopology; errors
// name shapeName and the face, at loc).
LoopMesh refineLoop(const LoopMesh& control, int levels, const LoopRules& rules,
                    const FileLoc& loc = {}, const std::string& shapeName = "loopsubdiv");

// The limit positions of mesh's vertices, and unit normals from the limit tangents, pointing the
// way the faces wind (counter-clockwise seen from the normal's side). A vertex no face uses keeps
// its position and gets a zero normal.
struct LoopLimit {
  std::vector<LoopPoint> p;
  std::vector<Normal3f> n;
};
LoopLimit loopLimit(const LoopMesh& mesh, const LoopTopology& topology, const LoopRules& rules);

// Values that follow the refinement linearly (uv, user normals): even vertices keep theirs, odd
// ones take the mean of their edge's ends, so each refined vertex gets the control face's
// barycentric interpolation of them.
template <typename T>
std::vector<T> refineLinearOnce(const std::vector<T>& values, const LoopTopology& topology) {
  std::vector<T> out(values);
  out.reserve(values.size() + topology.edges.size());
  for (const LoopTopology::Edge& e : topology.edges)
    out.push_back((values[e.v[0]] + values[e.v[1]]) * 0.5f);
  return out;
}

}  // namespace candela
