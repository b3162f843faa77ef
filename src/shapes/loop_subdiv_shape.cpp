#include "shapes/loop_subdiv_shape.h"

#include <cstdint>
#include <string>

#include "shapes/opensubdiv_loop.h"

namespace candela {

namespace {

constexpr const char* kName = "loopsubdiv";

}  // namespace

std::vector<std::unique_ptr<Shape>> createLoopSubdivShapes(
    const Transform& objectToWorld, bool reverseOrientation, const ParamSet& params,
    std::unique_ptr<TriangleMesh>* meshOut, const FileLoc& loc, LoopProducer producer) {
  auto err = [&](const char* name, const std::string& message) {
    throw SceneError(params.locationOf(name, loc), std::string(kName) + ": " + message);
  };
  // Each level multiplies the faces by 4: 8 levels turn one face into 65536.
  int levels = params.getOneInt("nlevels", 3, ValueRange::within(0, 8), loc);
  LoopMesh control;
  for (const Point3f& v : params.getPoint3fArray("P")) control.p.push_back(v);
  control.indices = params.getIntArray("indices");
  if (control.p.empty()) err("P", "missing \"point3 P\"");
  if (control.indices.empty()) err("indices", "missing \"integer indices\"");
  // Refinement keeps about 200 bytes per final face (the benchmark's peak heap): past this many
  // faces (13 GB) a scene would exhaust memory rather than fail clearly.
  constexpr int64_t kMaxRefinedFaces = int64_t(1) << 26;
  int64_t refinedFaces = int64_t(control.indices.size() / 3) << (2 * levels);
  if (refinedFaces > kMaxRefinedFaces)
    err("nlevels", std::string("\"nlevels\" ")
                       .append(std::to_string(levels))
                       .append(" would make ")
                       .append(std::to_string(refinedFaces))
                       .append(" triangles; at most ")
                       .append(std::to_string(kMaxRefinedFaces))
                       .append(" are allowed"));
  const char* uvName = params.find("uv") ? "uv" : "st";
  std::vector<Point2f> uv = params.getPoint2fArray(uvName);
  std::vector<Normal3f> n = params.getNormal3fArray("N");
  auto checkCount = [&](const char* name, size_t count) {
    if (count != 0 && count != control.p.size())
      // Appended piece by piece: "literal" + std::string trips GCC 12's -Wrestrict.
      err(name, std::string("\"")
                    .append(name)
                    .append("\" has ")
                    .append(std::to_string(count))
                    .append(" values but \"P\" has ")
                    .append(std::to_string(control.p.size())));
  };
  checkCount(uvName, uv.size());
  checkCount("N", n.size());

  std::vector<int> indices;
  std::vector<LoopPoint> p;
  std::vector<Normal3f> limitN;
  // Each producer validates the control mesh first (errors at "indices", naming the face).
  if (producer == LoopProducer::Book) {
    LoopTopology t = buildLoopTopology(control, params.locationOf("indices", loc), kName);
    LoopMesh mesh = control;
    for (int level = 0; level < levels; ++level) {
      if (!uv.empty()) uv = refineLinearOnce(uv, t);
      if (!n.empty()) n = refineLinearOnce(n, t);
      mesh = refineLoopOnce(mesh, t, kLoopSubdivShapeRules);
      t = buildLoopTopology(mesh, loc, kName);
    }
    LoopLimit limit = loopLimit(mesh, t, kLoopSubdivShapeRules);
    indices = std::move(mesh.indices);
    p = std::move(limit.p);
    limitN = std::move(limit.n);
  } else {
    // uv and N, when given, ride along as OpenSubdiv's varying (linear) data.
    std::vector<std::vector<LoopPoint>> linear;
    if (!uv.empty()) {
      std::vector<LoopPoint>& values = linear.emplace_back();
      for (const Point2f& v : uv) values.emplace_back(v.x, v.y, 0);
    }
    if (!n.empty()) {
      std::vector<LoopPoint>& values = linear.emplace_back();
      for (const Normal3f& v : n) values.emplace_back(v.x, v.y, v.z);
    }
    OsdLoopResult osd = refineLoopOpenSubdiv(control, levels, OsdBoundary::EdgeOnly,
                                             params.locationOf("indices", loc), kName, linear);
    indices = std::move(osd.refined.indices);
    p = std::move(osd.limitP);
    limitN = std::move(osd.limitN);
    size_t channel = 0;
    if (!uv.empty()) {
      uv.clear();
      for (const LoopPoint& v : osd.linear[channel++]) uv.emplace_back(Float(v.x), Float(v.y));
    }
    if (!n.empty()) {
      n.clear();
      for (const LoopPoint& v : osd.linear[channel++])
        n.emplace_back(Float(v.x), Float(v.y), Float(v.z));
    }
  }
  if (n.empty()) {
    n = std::move(limitN);
  } else {
    for (Normal3f& v : n)
      if (v.length() > 0) v = normalize(v);
  }
  std::vector<Point3f> positions;
  positions.reserve(p.size());
  for (const LoopPoint& v : p) positions.push_back(v.toPoint3f());
  auto triangles = std::make_unique<TriangleMesh>(
      objectToWorld, reverseOrientation, std::move(indices), std::move(positions), std::move(n),
      std::vector<Vector3f>(), std::move(uv));
  std::vector<std::unique_ptr<Shape>> shapes = createTriangleShapes(triangles.get());
  *meshOut = std::move(triangles);
  return shapes;
}

}  // namespace candela
