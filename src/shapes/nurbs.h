// The "nurbs" shape (lrt draft App. C lists it; pbrt-v2's semantics): a tensor-product NURBS
// surface, never intersected directly. As pbrt-v2 does, it is evaluated once at scene build on a
// regular grid of (u, v) and becomes a triangle mesh whose vertices carry the exact surface
// normals (from the derivatives) and their (u, v), handed to the triangle-mesh code.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "shapes/triangle_mesh.h"

namespace candela {

// nu x nv control points of orders uorder, vorder (degrees one less) over nu + uorder and
// nv + vorder knots. Control point (i, j) is pw[j nu + i] (u fastest), homogeneous: (w x, w y,
// w z, w) stands for the point (x, y, z) of weight w (RenderMan's and pbrt-v2's "Pw"); a
// non-rational surface has w = 1.
struct NurbsSurface {
  int nu = 0, uorder = 0, nv = 0, vorder = 0;
  std::vector<double> uknots, vknots;
  std::vector<std::array<double, 4>> pw;
};

struct NurbsSample {
  std::array<double, 3> p, dpdu, dpdv, d2pdudv;
};

// The point and its partial derivatives at (u, v) inside both valid knot ranges (The NURBS Book,
// §4.4, A4.3 for the point; the derivatives by the quotient rule, §4.5: with A(u, v) the
// homogeneous sum and w its weight, S_u = (A_u - w_u S) / w, the same for v; the mixed
// derivative, used at poles, likewise from A_uv).
NurbsSample evaluateNurbs(const NurbsSurface& surface, double u, double v);

// The surface at diceu x dicev (u, v) evenly spaced over [u0, u1] x [v0, v1]: vertex (i, j) is
// sample j diceu + i with uv (u_i, v_j); each grid cell is two triangles wound counterclockwise
// in (u, v), so that dp/du x dp/dv, the vertex normal, is on the winding's side. A grid line on a
// knot takes the span to its right, except the last (u1, v1), which takes the patch's own, to its
// left. Where the cross product vanishes, the normal is its limit from that span at a pole (a row
// or column of control points collapsed to one point), else the surface normal a small step
// inside, else the average of the neighbouring triangles' normals, else +z: never NaN.
std::unique_ptr<TriangleMesh> makeNurbsMesh(const Transform& objectToWorld, bool reverseOrientation,
                                            const NurbsSurface& surface, double u0, double u1,
                                            double v0, double v1, int diceu, int dicev);

// "nurbs": "integer nu", "uorder" (1 <= uorder <= nu), "float uknots" (nu + uorder,
// nondecreasing), optional "float u0", "u1" (default and limits: the valid range uknots[uorder -
// 1] .. uknots[nu]); the same for v; "point P" (nu nv points, u fastest) or "float Pw" (nu nv
// homogeneous x y z w, w > 0). Candela extension: "integer diceu", "dicev" (default 30, pbrt-v2's
// fixed grid), the vertices along each direction. Bad parameters, control points beyond float's
// range and a surface the transform carries beyond it: SceneError at the parameter.
std::vector<std::unique_ptr<Shape>> createNurbsShapes(const Transform& objectToWorld,
                                                      bool reverseOrientation,
                                                      const ParamSet& params,
                                                      std::unique_ptr<TriangleMesh>* meshOut,
                                                      const FileLoc& loc);

}  // namespace candela
