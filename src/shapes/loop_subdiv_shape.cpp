#include "shapes/loop_subdiv_shape.h"

#include <string>

#include "shapes/opensubdiv_loop.h"

namespace candela {

namespace {

constexpr const char* kName = "loopsubdiv";

template <typename T>
std::vector<T> permuted(const std::vector<T>& ours, const std::vector<int>& fromOurs) {
  std::vector<T> out(ours.size());
  for (size_t i = 0; i < ours.size(); ++i) out[fromOurs[i]] = ours[i];
  return out;
}

}  // namespace

std::vector<std::unique_ptr<Shape>> createLoopSubdivShapes(
    const Transform& objectToWorld, bool reverseOrientation, const ParamSet& params,
    std::unique_ptr<TriangleMesh>* meshOut, const FileLoc& loc, LoopProducer producer) {
  auto err = [&](const char* name, const std::string& message) {
    throw SceneError(params.locationOf(name, loc), std::string(kName) + ": " + message);
  };
  // Each level multiplies the faces by 4: 8 levels turn one face into 65536.
  int levels = params.getOneInt("nlevels", 3);
  if (levels < 0 || levels > 8)
    err("nlevels", "\"nlevels\" must be in [0, 8], found " + std::to_string(levels));
  LoopMesh control{params.getPoint3fArray("P"), params.getIntArray("indices")};
  if (control.p.empty()) err("P", "missing \"point3 P\"");
  if (control.indices.empty()) err("indices", "missing \"integer indices\"");
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

  // The linear values follow our refinement (validating the topology first).
  LoopTopology t = buildLoopTopology(control, params.locationOf("indices", loc), kName);
  LoopMesh mesh = control;
  const LoopRules book{LoopRules::Warren, LoopRules::Book};
  for (int level = 0; level < levels; ++level) {
    if (!uv.empty()) uv = refineLinearOnce(uv, t);
    if (!n.empty()) n = refineLinearOnce(n, t);
    mesh = refineLoopOnce(mesh, t, book);
    t = buildLoopTopology(mesh, loc, kName);
  }
  std::vector<Point3f> p;
  std::vector<Normal3f> limitN;
  if (producer == LoopProducer::Book) {
    LoopLimit limit = loopLimit(mesh, t, book);
    p = std::move(limit.p);
    limitN = std::move(limit.n);
  } else {
    OsdLoopResult osd = refineLoopOpenSubdiv(control, levels, OsdBoundary::EdgeOnly, loc, kName);
    mesh.indices = std::move(osd.refined.indices);
    p = std::move(osd.limitP);
    limitN = std::move(osd.limitN);
    if (!uv.empty()) uv = permuted(uv, osd.fromOurs);
    if (!n.empty()) n = permuted(n, osd.fromOurs);
  }
  if (n.empty()) {
    n = std::move(limitN);
  } else {
    for (Normal3f& v : n)
      if (v.length() > 0) v = normalize(v);
  }
  auto triangles = std::make_unique<TriangleMesh>(
      objectToWorld, reverseOrientation, std::move(mesh.indices), std::move(p), std::move(n),
      std::vector<Vector3f>(), std::move(uv));
  std::vector<std::unique_ptr<Shape>> shapes = createTriangleShapes(triangles.get());
  *meshOut = std::move(triangles);
  return shapes;
}

}  // namespace candela
