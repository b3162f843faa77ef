// The "heightfield" shape (lrt draft App. C lists it without code; pbrt-v2's semantics): nu x nv
// heights Pz over the unit square in object space, row by row (u fastest), become a triangle
// mesh of two triangles per cell with (u, v) = (x, y), handed to the triangle-mesh code.
#pragma once

#include <memory>
#include <vector>

#include "shapes/triangle_mesh.h"

namespace candela {

// The mesh of a heightfield: vertex (i, j) at (i / (nu - 1), j / (nv - 1), z[j nu + i]). Cells are
// split along the diagonal from (i, j) to (i + 1, j + 1); the triangles' winding gives normals
// with a positive z component. Requires nu, nv >= 2 and z.size() == nu nv.
std::unique_ptr<TriangleMesh> makeHeightfieldMesh(const Transform& objectToWorld,
                                                  bool reverseOrientation, int nu, int nv,
                                                  const std::vector<Float>& z);

// "heightfield": "nu", "nv" (integers >= 2), "Pz" (nu * nv floats). Throws SceneError at the
// offending parameter for missing or wrong counts and non-finite heights.
std::vector<std::unique_ptr<Shape>> createHeightfieldShapes(const Transform& objectToWorld,
                                                            bool reverseOrientation,
                                                            const ParamSet& params,
                                                            std::unique_ptr<TriangleMesh>* meshOut,
                                                            const FileLoc& loc);

}  // namespace candela
