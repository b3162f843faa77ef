#include "shapes/opensubdiv_loop.h"

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>
#include <cmath>
#include <memory>

namespace candela {

namespace {

using namespace OpenSubdiv;

// The primvar type PrimvarRefiner interpolates: it needs Clear and AddWithWeight (dependencies.md
// §6). In double, with PrimvarRefinerReal<double>'s double weights: see LoopPoint for why.
struct OsdPoint {
  double x = 0, y = 0, z = 0;
  void Clear(void* = nullptr) { x = y = z = 0; }
  void AddWithWeight(const OsdPoint& s, double w) { x += w * s.x, y += w * s.y, z += w * s.z; }
};
using OsdPrimvarRefiner = Far::PrimvarRefinerReal<double>;

std::vector<OsdPoint> toOsd(const std::vector<LoopPoint>& points) {
  std::vector<OsdPoint> out(points.size());
  for (size_t i = 0; i < points.size(); ++i) out[i] = {points[i].x, points[i].y, points[i].z};
  return out;
}

OsdPoint cross(const OsdPoint& a, const OsdPoint& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
OsdPoint minus(const OsdPoint& a, const OsdPoint& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
double dot(const OsdPoint& a, const OsdPoint& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

std::unique_ptr<Far::TopologyRefiner> createRefiner(const LoopMesh& control, OsdBoundary boundary) {
  Sdc::Options sdc;
  sdc.SetVtxBoundaryInterpolation(boundary == OsdBoundary::EdgeOnly
                                      ? Sdc::Options::VTX_BOUNDARY_EDGE_ONLY
                                      : Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
  std::vector<int> counts(control.faceCount(), 3);
  Far::TopologyDescriptor desc;
  desc.numVertices = int(control.p.size());
  desc.numFaces = control.faceCount();
  desc.numVertsPerFace = counts.data();
  desc.vertIndicesPerFace = control.indices.data();
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  return std::unique_ptr<Far::TopologyRefiner>(
      Factory::Create(desc, Factory::Options(Sdc::SCHEME_LOOP, sdc)));
}

// Follows our numbering level by level through OpenSubdiv's child-vertex relations.
std::vector<int> mapOurVertices(const LoopMesh& control, int levels,
                                const Far::TopologyRefiner& refiner, const FileLoc& loc,
                                const std::string& shapeName) {
  std::vector<int> map(control.p.size());
  for (size_t i = 0; i < map.size(); ++i) map[i] = int(i);
  LoopMesh mesh = control;
  for (int l = 0; l < levels; ++l) {
    LoopTopology t = buildLoopTopology(mesh, loc, shapeName);
    const Far::TopologyLevel& level = refiner.GetLevel(l);
    std::vector<int> next(mesh.p.size() + t.edges.size());
    for (size_t v = 0; v < mesh.p.size(); ++v) next[v] = level.GetVertexChildVertex(map[v]);
    for (size_t e = 0; e < t.edges.size(); ++e)
      next[mesh.p.size() + e] =
          level.GetEdgeChildVertex(level.FindEdge(map[t.edges[e].v[0]], map[t.edges[e].v[1]]));
    map.swap(next);
    mesh = refineLoopOnce(mesh, t, LoopRules{});
  }
  return map;
}

}  // namespace

OsdLoopResult refineLoopOpenSubdiv(const LoopMesh& control, int levels, OsdBoundary boundary,
                                   const FileLoc& loc, const std::string& shapeName,
                                   const std::vector<std::vector<LoopPoint>>& linear) {
  buildLoopTopology(control, loc, shapeName);
  std::unique_ptr<Far::TopologyRefiner> refiner = createRefiner(control, boundary);
  if (!refiner) throw SceneError(loc, shapeName + ": OpenSubdiv rejected the mesh");
  // Without the full topology of the last level Limit() leaves its output at zero
  // (dependencies.md §6).
  Far::TopologyRefiner::UniformOptions options(levels);
  options.fullTopologyInLastLevel = true;
  if (levels > 0) refiner->RefineUniform(options);

  OsdPrimvarRefiner primvars(*refiner);
  std::vector<OsdPoint> p = toOsd(control.p);
  std::vector<std::vector<OsdPoint>> varying;
  for (const std::vector<LoopPoint>& values : linear) varying.push_back(toOsd(values));
  for (int l = 1; l <= levels; ++l) {
    std::vector<OsdPoint> next(refiner->GetLevel(l).GetNumVertices());
    primvars.Interpolate(l, p, next);
    p.swap(next);
    for (std::vector<OsdPoint>& values : varying) {
      std::vector<OsdPoint> refined(p.size());
      primvars.InterpolateVarying(l, values, refined);
      values.swap(refined);
    }
  }
  std::vector<OsdPoint> limit(p.size()), tan1(p.size()), tan2(p.size());
  primvars.Limit(p, limit, tan1, tan2);

  OsdLoopResult out;
  const Far::TopologyLevel& last = refiner->GetLevel(levels);
  for (int f = 0; f < last.GetNumFaces(); ++f)
    for (int v : last.GetFaceVertices(f)) out.refined.indices.push_back(v);
  // OpenSubdiv's tangents need not be ordered with the winding: the sum of the incident faces'
  // normals decides the side.
  std::vector<OsdPoint> faceSide(p.size());
  for (int f = 0; f < last.GetNumFaces(); ++f) {
    const int* v = &out.refined.indices[3 * f];
    OsdPoint n = cross(minus(p[v[1]], p[v[0]]), minus(p[v[2]], p[v[0]]));
    for (int i = 0; i < 3; ++i) faceSide[v[i]].AddWithWeight(n, 1);
  }
  for (size_t i = 0; i < p.size(); ++i) {
    out.refined.p.emplace_back(p[i].x, p[i].y, p[i].z);
    out.limitP.emplace_back(limit[i].x, limit[i].y, limit[i].z);
    OsdPoint n = cross(tan1[i], tan2[i]);
    double len = std::sqrt(dot(n, n)) * (dot(n, faceSide[i]) < 0 ? -1 : 1);
    out.limitN.push_back(len != 0 ? Normal3f(Float(n.x / len), Float(n.y / len), Float(n.z / len))
                                  : Normal3f());
  }
  for (const std::vector<OsdPoint>& values : varying) {
    std::vector<LoopPoint>& to = out.linear.emplace_back();
    for (const OsdPoint& v : values) to.emplace_back(v.x, v.y, v.z);
  }
  return out;
}

std::vector<int> openSubdivIndexOfOurs(const LoopMesh& control, int levels) {
  buildLoopTopology(control, {}, "loopsubdiv");
  std::unique_ptr<Far::TopologyRefiner> refiner = createRefiner(control, OsdBoundary::EdgeOnly);
  Far::TopologyRefiner::UniformOptions options(levels);
  if (levels > 0) refiner->RefineUniform(options);
  return mapOurVertices(control, levels, *refiner, {}, "loopsubdiv");
}

}  // namespace candela
