#include "shapes/loop_subdiv_topology.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace candela {

double distance(const LoopPoint& a, const LoopPoint& b) {
  return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) +
                   (a.z - b.z) * (a.z - b.z));
}

int LoopTopology::opposite(const LoopMesh& mesh, int f, int e) const {
  for (int i = 0; i < 3; ++i) {
    int v = mesh.indices[3 * f + i];
    if (v != edges[e].v[0] && v != edges[e].v[1]) return v;
  }
  return -1;
}

namespace {

struct Builder {
  const LoopMesh& mesh;
  const FileLoc& loc;
  const std::string& shape;
  LoopTopology t;
  std::vector<int> edgeFrom;  // the start vertex of each edge as its first face winds it
  std::unordered_map<std::uint64_t, int> edgeIndex;

  [[noreturn]] void fail(int face, const std::string& message) const {
    throw SceneError(loc, shape + ": face " + std::to_string(face) + " " + message);
  }
  int corner(int f, int i) const { return mesh.indices[3 * f + i % 3]; }
  static std::uint64_t key(int a, int b) {
    return (std::uint64_t(std::uint32_t(std::min(a, b))) << 32) | std::uint32_t(std::max(a, b));
  }
  int findEdge(int a, int b) const {
    auto it = edgeIndex.find(key(a, b));
    return it == edgeIndex.end() ? -1 : it->second;
  }

  void checkFaces() {
    if (mesh.indices.empty() || mesh.indices.size() % 3 != 0)
      throw SceneError(loc, shape + ": \"indices\" must hold 3 per triangle, found " +
                                std::to_string(mesh.indices.size()));
    int nv = int(mesh.p.size());
    for (int f = 0; f < mesh.faceCount(); ++f)
      for (int i = 0; i < 3; ++i) {
        int v = corner(f, i);
        if (v < 0 || v >= nv)
          fail(f, "has vertex index " + std::to_string(v) + ", out of range [0, " +
                      std::to_string(nv) + ")");
        if (v == corner(f, i + 1)) fail(f, "repeats vertex " + std::to_string(v));
      }
  }

  // Each undirected edge once; a manifold, consistently oriented mesh has each directed edge at
  // most once (seed 000 §3 "subdiv": the draft's input requirements).
  void linkEdges() {
    t.faceEdges.resize(mesh.indices.size());
    for (int f = 0; f < mesh.faceCount(); ++f)
      for (int i = 0; i < 3; ++i) {
        int a = corner(f, i), b = corner(f, i + 1);
        auto [it, added] = edgeIndex.try_emplace(key(a, b), int(t.edges.size()));
        if (added) {
          t.edges.push_back({{std::min(a, b), std::max(a, b)}, {f, -1}});
          edgeFrom.push_back(a);
        } else {
          LoopTopology::Edge& e = t.edges[it->second];
          if (e.f[1] != -1)
            fail(f, "has edge (" + std::to_string(a) + ", " + std::to_string(b) +
                        ") already shared by faces " + std::to_string(e.f[0]) + " and " +
                        std::to_string(e.f[1]) + " (an edge may have at most two faces)");
          if (edgeFrom[it->second] == a)
            fail(f, "winds edge (" + std::to_string(a) + ", " + std::to_string(b) +
                        ") the same way as face " + std::to_string(e.f[0]) +
                        " (inconsistent orientation)");
          e.f[1] = f;
        }
        t.faceEdges[3 * f + i] = it->second;
      }
  }

  int otherFace(int e, int f) const {
    return t.edges[e].f[0] == f ? t.edges[e].f[1] : t.edges[e].f[0];
  }

  // Walks the faces around v counter-clockwise: from face (v, a, b) across edge (v, b) to the face
  // whose a is this b. A boundary vertex starts at the face whose edge (v, a) has no other face.
  void buildRings() {
    int nv = int(mesh.p.size());
    std::vector<std::vector<int>> faces(nv);
    for (int f = 0; f < mesh.faceCount(); ++f)
      for (int i = 0; i < 3; ++i) faces[corner(f, i)].push_back(f);
    t.rings.resize(nv);
    t.boundary.assign(nv, 0);
    auto local = [&](int f, int v) {
      for (int i = 0; i < 3; ++i)
        if (corner(f, i) == v) return i;
      return -1;
    };
    for (int v = 0; v < nv; ++v) {
      if (faces[v].empty()) continue;
      int start = faces[v][0];
      for (int f : faces[v]) {
        int i = local(f, v);
        if (otherFace(findEdge(v, corner(f, i + 1)), f) == -1) {
          start = f;
          t.boundary[v] = 1;
          break;
        }
      }
      std::vector<int>& ring = t.rings[v];
      int f = start;
      size_t visited = 0;
      while (true) {
        int i = local(f, v);
        ring.push_back(corner(f, i + 1));
        ++visited;
        int next = otherFace(findEdge(v, corner(f, i + 2)), f);
        if (next == -1) {
          ring.push_back(corner(f, i + 2));
          break;
        }
        if (next == start || visited > faces[v].size()) break;
        f = next;
      }
      if (visited != faces[v].size()) {
        // The faces around v form more than one fan: name one the walk did not reach.
        int missed = faces[v][0];
        for (int g : faces[v])
          if (std::find(ring.begin(), ring.end(), corner(g, local(g, v) + 1)) == ring.end())
            missed = g;
        fail(missed, "meets the other faces at vertex " + std::to_string(v) +
                         " only at that vertex (non-manifold vertex)");
      }
    }
  }
};

}  // namespace

LoopTopology buildLoopTopology(const LoopMesh& mesh, const FileLoc& loc,
                               const std::string& shapeName) {
  Builder b{mesh, loc, shapeName, {}, {}, {}};
  b.checkFaces();
  b.linkEdges();
  b.buildRings();
  return std::move(b.t);
}

}  // namespace candela
