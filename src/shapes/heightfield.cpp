#include "shapes/heightfield.h"

#include <string>

namespace candela {

std::unique_ptr<TriangleMesh> makeHeightfieldMesh(const Transform& objectToWorld,
                                                  bool reverseOrientation, int nu, int nv,
                                                  const std::vector<Float>& z) {
  std::vector<Point3f> p;
  std::vector<Point2f> uv;
  p.reserve(z.size());
  uv.reserve(z.size());
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      Float x = Float(i) / Float(nu - 1), y = Float(j) / Float(nv - 1);
      p.emplace_back(x, y, z[size_t(j) * nu + i]);
      uv.emplace_back(x, y);
    }
  std::vector<int> indices;
  indices.reserve(size_t(nu - 1) * (nv - 1) * 6);
  auto vertex = [nu](int i, int j) { return j * nu + i; };
  for (int j = 0; j + 1 < nv; ++j)
    for (int i = 0; i + 1 < nu; ++i) {
      // Counter-clockwise seen from +z, as pbrt-v2's heightfield.
      for (int k : {vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j),
                    vertex(i + 1, j + 1), vertex(i, j + 1)})
        indices.push_back(k);
    }
  return std::make_unique<TriangleMesh>(objectToWorld, reverseOrientation, std::move(indices),
                                        std::move(p), std::vector<Normal3f>(),
                                        std::vector<Vector3f>(), std::move(uv));
}

std::vector<std::unique_ptr<Shape>> createHeightfieldShapes(const Transform& objectToWorld,
                                                            bool reverseOrientation,
                                                            const ParamSet& params,
                                                            std::unique_ptr<TriangleMesh>* meshOut,
                                                            const FileLoc& loc) {
  auto err = [&](const char* name, const std::string& message) {
    throw SceneError(params.locationOf(name, loc), "heightfield: " + message);
  };
  int nu = params.getOneInt("nu", -1), nv = params.getOneInt("nv", -1);
  if (!params.find("nu")) err("nu", "missing \"integer nu\"");
  if (!params.find("nv")) err("nv", "missing \"integer nv\"");
  params.requireInRange("nu", nu, ValueRange::atLeast(2), loc);
  params.requireInRange("nv", nv, ValueRange::atLeast(2), loc);
  // Products of two ints checked in 64 bits; a mesh has int vertex indices.
  long long count = (long long)nu * nv;
  if (count > (1LL << 30)) err("nu", "nu * nv = " + std::to_string(count) + " is too large");
  std::vector<Float> z = params.getFloatArray("Pz");
  if (z.empty()) err("Pz", "missing \"float Pz\" (nu * nv heights)");
  if ((long long)z.size() != count)
    err("Pz", "\"Pz\" has " + std::to_string(z.size()) + " values but nu * nv = " +
                  std::to_string(nu) + " * " + std::to_string(nv) + " = " + std::to_string(count));
  for (size_t i = 0; i < z.size(); ++i)
    if (!std::isfinite(z[i])) err("Pz", "\"Pz\"[" + std::to_string(i) + "] is not finite");
  std::unique_ptr<TriangleMesh> mesh =
      makeHeightfieldMesh(objectToWorld, reverseOrientation, nu, nv, z);
  std::vector<std::unique_ptr<Shape>> shapes = createTriangleShapes(mesh.get());
  *meshOut = std::move(mesh);
  return shapes;
}

}  // namespace candela
