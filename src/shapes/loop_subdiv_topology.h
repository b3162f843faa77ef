// Mesh topology for Loop subdivision (lrt draft §3.7, seed 000 inventory §3 "subdiv"): the edges
// with the faces on either side, and each vertex's ordered one-ring. Built from an index list
// alone, after checking that the mesh is one the rules apply to: a consistently oriented
// manifold triangle mesh, open or closed.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/vector.h"

namespace candela {

// A point of a control or refined mesh. Refinement and the limit run in double: near some boundary
// vertices of the killeroo the limit normal is so ill-conditioned that float positions turn it by
// up to 6e-3 rad by level 4 (OpenSubdiv's own float and double results differ that much there).
struct LoopPoint {
  double x = 0, y = 0, z = 0;
  LoopPoint() = default;
  LoopPoint(double x, double y, double z) : x(x), y(y), z(z) {}
  // Implicit: control points arrive as Point3f, and each is exact in double.
  LoopPoint(const Point3f& p) : x(p.x), y(p.y), z(p.z) {}
  Point3f toPoint3f() const { return Point3f(Float(x), Float(y), Float(z)); }
  bool operator==(const LoopPoint&) const = default;
};
double distance(const LoopPoint& a, const LoopPoint& b);
// The difference in double, rounded to float: for comparisons and tests.
inline Vector3f operator-(const LoopPoint& a, const LoopPoint& b) {
  return Vector3f(Float(a.x - b.x), Float(a.y - b.y), Float(a.z - b.z));
}

// A triangle mesh: three indices into p per face.
struct LoopMesh {
  std::vector<LoopPoint> p;
  std::vector<int> indices;
  int faceCount() const { return int(indices.size() / 3); }
};

struct LoopTopology {
  struct Edge {
    int v[2];  // v[0] < v[1]
    int f[2];  // the faces on either side; f[1] = -1 on a boundary
  };
  std::vector<Edge> edges;
  // Three per face: faceEdges[3 f + i] is the edge from corner i to corner i + 1.
  std::vector<int> faceEdges;
  // Vertex v's neighbours in counter-clockwise order (as the faces wind). On a boundary the first
  // and last are the neighbours along the boundary, and the ring has one more vertex than the
  // vertex has faces; inside, one per face. Empty for a vertex no face uses.
  std::span<const int> ring(int v) const {
    return {ringVertices.data() + ringStart[v], size_t(ringSize[v])};
  }
  std::vector<char> boundary;  // per vertex

  // The rings, flat: vertex v's occupies ringSize[v] entries from ringStart[v] (one per face
  // around it, plus one reserved for a boundary), so a level's rings are three allocations, not
  // one per vertex.
  std::vector<int> ringVertices, ringStart, ringSize;

  // The vertex of face f that is on neither end of edge e (e must be an edge of f).
  int opposite(const LoopMesh& mesh, int f, int e) const;
};

// Throws SceneError at loc, naming shapeName and the face, when an index is out of range, a face
// repeats a vertex, an edge has more than two faces, two faces sharing an edge wind it the same
// way (inconsistent orientation), or a vertex's faces do not form a single fan (non-manifold).
LoopTopology buildLoopTopology(const LoopMesh& mesh, const FileLoc& loc,
                               const std::string& shapeName);

}  // namespace candela
