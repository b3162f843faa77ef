#include "shapes/shape_plugins.h"

#include "shapes/cone.h"
#include "shapes/curve_shape.h"
#include "shapes/cylinder.h"
#include "shapes/disk.h"
#include "shapes/heightfield.h"
#include "shapes/hyperboloid.h"
#include "shapes/loop_subdiv_shape.h"
#include "shapes/nurbs.h"
#include "shapes/paraboloid.h"
#include "shapes/sphere.h"
#include "shapes/triangle_mesh.h"

namespace candela {

namespace {

using Shapes = std::vector<std::unique_ptr<Shape>>;

Shapes single(std::unique_ptr<Shape> shape) {
  Shapes out;
  out.push_back(std::move(shape));
  return out;
}

// The quadrics but the hyperboloid need nothing beyond placement and parameters.
template <std::unique_ptr<Shape> (*Make)(const Transform&, bool, const ParamSet&)>
Shapes quadric(const ShapeInputs& in, std::unique_ptr<TriangleMesh>* /*meshOut*/) {
  return single(Make(in.objectToWorld, in.reverseOrientation, in.params));
}

Shapes hyperboloid(const ShapeInputs& in, std::unique_ptr<TriangleMesh>* /*meshOut*/) {
  return single(createHyperboloidShape(in.objectToWorld, in.reverseOrientation, in.params,
                                       in.hyperboloidNormal));
}

Shapes heightfield(const ShapeInputs& in, std::unique_ptr<TriangleMesh>* meshOut) {
  return createHeightfieldShapes(in.objectToWorld, in.reverseOrientation, in.params, meshOut,
                                 in.loc);
}

Shapes triangleMesh(const ShapeInputs& in, std::unique_ptr<TriangleMesh>* meshOut) {
  return createTriangleMeshShapes(in.objectToWorld, in.reverseOrientation, in.params, meshOut,
                                  in.loc);
}

Shapes plyMesh(const ShapeInputs& in, std::unique_ptr<TriangleMesh>* meshOut) {
  return createPlyMeshShapes(in.objectToWorld, in.reverseOrientation, in.params, meshOut, in.loc,
                             in.directory);
}

Shapes loopSubdiv(const ShapeInputs& in, std::unique_ptr<TriangleMesh>* meshOut) {
  return createLoopSubdivShapes(in.objectToWorld, in.reverseOrientation, in.params, meshOut, in.loc,
                                in.subdiv);
}

Shapes nurbs(const ShapeInputs& in, std::unique_ptr<TriangleMesh>* meshOut) {
  return createNurbsShapes(in.objectToWorld, in.reverseOrientation, in.params, meshOut, in.loc);
}

Shapes curve(const ShapeInputs& in, std::unique_ptr<TriangleMesh>* /*meshOut*/) {
  return createCurveShapes(in.objectToWorld, in.reverseOrientation, in.params, in.loc);
}

// quadricPhiMax: the quadrics' sweep angle under either name; phimax wins when both are given.
constexpr std::array<ParamSpec, 2> kSweep = {{
    {"phimax", "float", "360", "", "", kPbrt, "sweep angle in degrees, clamped to [0, 360]"},
    {"thetamax", "float", "(phimax, else 360)", "", "", kLrt,
     "the lrt draft's name for phimax, read when phimax is absent"},
}};

constexpr auto kSphereParams =
    joinParams(std::to_array<ParamSpec>({
                   {"radius", "float", "1", "", "positive and finite", kAllDialects, "radius"},
                   {"zmin", "float", "(-radius)", "", "finite", kAllDialects,
                    "lowest z kept (clamped to the radius)"},
                   {"zmax", "float", "(radius)", "", "finite", kAllDialects,
                    "highest z kept (clamped to the radius)"},
               }),
               kSweep);

constexpr auto kCylinderParams =
    joinParams(std::to_array<ParamSpec>({
                   {"radius", "float", "1", "", "positive and finite", kAllDialects, "radius"},
                   {"zmin", "float", "-1", "", "finite", kAllDialects, "one end's z"},
                   {"zmax", "float", "1", "", "finite", kAllDialects, "the other end's z"},
               }),
               kSweep);

constexpr auto kDiskParams = joinParams(
    std::to_array<ParamSpec>({
        {"height", "float", "0", "", "finite", kAllDialects, "z of the disk's plane"},
        {"radius", "float", "1", "", "positive and finite", kAllDialects, "outer radius"},
        {"innerradius", "float", "0", "", "non-negative and finite", kPbrt,
         "inner radius, below radius: a ring"},
    }),
    kSweep);

constexpr auto kConeParams = joinParams(std::to_array<ParamSpec>({
                                            {"radius", "float", "1", "", "positive and finite",
                                             kAllDialects, "radius of the base at z = 0"},
                                            {"height", "float", "1", "", "finite", kAllDialects,
                                             "z of the apex, not 0 (negative: pointing down)"},
                                        }),
                                        kSweep);

constexpr auto kParaboloidParams = joinParams(
    std::to_array<ParamSpec>({
        {"radius", "float", "1", "", "positive and finite", kAllDialects, "radius at zmax"},
        {"zmin", "float", "0", "", "finite", kAllDialects, "lowest z kept"},
        {"zmax", "float", "1", "", "finite", kAllDialects,
         "highest z kept (zmin or zmax must be above 0)"},
    }),
    kSweep);

constexpr auto kHyperboloidParams = joinParams(
    std::to_array<ParamSpec>({
        {"p1", "point3", "0 0 0", "", "finite", kAllDialects, "one end of the swept segment"},
        {"p2", "point3", "1 1 1", "", "finite", kAllDialects,
         "the other end, at another z than p1"},
    }),
    kSweep);

constexpr ParamSpec kHeightfieldParams[] = {
    {"nu", "integer", "(required)", "", "at least 2", kAllDialects, "heights along x"},
    {"nv", "integer", "(required)", "", "at least 2", kAllDialects, "heights along y"},
    {"Pz", "float[]", "(required)", "", "finite", kAllDialects,
     "nu * nv heights over the unit square, x fastest"},
};

constexpr ParamSpec kTriangleMeshParams[] = {
    {"indices", "integer[]", "(0 1 2 when P has 3 points, else required)", "", "", kAllDialects,
     "3 vertex indices per triangle"},
    {"P", "point3[]", "(required)", "", "", kAllDialects, "vertex positions"},
    {"N", "normal3[]", "(none)", "", "", kAllDialects, "per-vertex shading normals"},
    {"S", "vector3[]", "(none)", "", "", kAllDialects, "per-vertex shading tangents"},
    {"uv", "point2[]", "(none)", "", "", kAllDialects, "per-vertex (u, v)"},
    {"st", "point2[]", "(none)", "", "", kPbrt, "pbrt's other name for uv, read when uv is absent"},
    // Read by assembly (shape_factory.cpp), which owns the textures.
    {"alpha", "float texture", "1", "", "", kPbrt, "cut-out: hits where it is 0 are ignored"},
    {"shadowalpha", "float texture", "1", "", "", kPbrtV3,
     "cut-out for shadow rays only, besides alpha"},
};

constexpr ParamSpec kPlyMeshParams[] = {
    {"filename", "string", "(required)", "", "", kPbrtV3,
     "PLY file, relative to the scene file's directory"},
    // Read by assembly (shape_factory.cpp), which owns the textures.
    {"alpha", "float texture", "1", "", "", kPbrtV3, "cut-out: hits where it is 0 are ignored"},
    {"shadowalpha", "float texture", "1", "", "", kPbrtV3,
     "cut-out for shadow rays only, besides alpha"},
};

constexpr ParamSpec kLoopSubdivParams[] = {
    {"nlevels", "integer", "3", "", "within [0, 8]", kAllDialects,
     "refinement levels (each makes 4 faces of one)"},
    {"P", "point3[]", "(required)", "", "", kAllDialects, "control vertex positions"},
    {"indices", "integer[]", "(required)", "", "", kAllDialects, "3 vertex indices per face"},
    {"uv", "point2[]", "(none)", "", "", kCandela,
     "per-control-vertex (u, v), carried through linearly"},
    {"st", "point2[]", "(none)", "", "", kCandela, "another name for uv, read when uv is absent"},
    {"N", "normal3[]", "(none)", "", "", kCandela,
     "per-control-vertex normals, used instead of the limit normals"},
};

constexpr ParamSpec kNurbsParams[] = {
    {"nu", "integer", "(required)", "", "at least 1", kAllDialects, "control points along u"},
    {"uorder", "integer", "(required)", "", "at least 1", kAllDialects,
     "order along u (degree + 1), at most nu"},
    {"uknots", "float[]", "(required)", "", "", kAllDialects,
     "nu + uorder finite, nondecreasing knots"},
    {"u0", "float", "(uknots[uorder - 1])", "", "finite", kAllDialects,
     "start of the u range, within the knots' (below u1)"},
    {"u1", "float", "(uknots[nu])", "", "finite", kAllDialects,
     "end of the u range, within the knots'"},
    {"diceu", "integer", "30", "", "at least 2", kCandela,
     "mesh vertices along u (pbrt-v2's fixed grid)"},
    {"nv", "integer", "(required)", "", "at least 1", kAllDialects, "control points along v"},
    {"vorder", "integer", "(required)", "", "at least 1", kAllDialects,
     "order along v (degree + 1), at most nv"},
    {"vknots", "float[]", "(required)", "", "", kAllDialects,
     "nv + vorder finite, nondecreasing knots"},
    {"v0", "float", "(vknots[vorder - 1])", "", "finite", kAllDialects,
     "start of the v range, within the knots' (below v1)"},
    {"v1", "float", "(vknots[nv])", "", "finite", kAllDialects,
     "end of the v range, within the knots'"},
    {"dicev", "integer", "30", "", "at least 2", kCandela,
     "mesh vertices along v (pbrt-v2's fixed grid)"},
    {"P", "point3[]", "(required, or Pw)", "", "finite", kAllDialects,
     "nu * nv control points, u fastest"},
    {"Pw", "float[]", "(none)", "", "", kAllDialects,
     "instead of P: nu * nv homogeneous points w x, w y, w z, w with w > 0"},
};

constexpr ParamSpec kCurveParams[] = {
    {"basis", "string", "bezier", "", "one of bezier, bspline", kPbrtV3,
     "Bézier segments sharing end points, or a uniform B-spline"},
    {"degree", "integer", "3", "", "within [2, 3]", kPbrtV3, "quadratic or cubic segments"},
    {"type", "string", "flat", "", "one of flat, cylinder, ribbon", kPbrtV3,
     "a strip facing the ray, a round tube, or a band oriented by N"},
    {"P", "point3[]", "(required)", "", "finite", kPbrtV3,
     "control points: 1 + degree k (Bézier) or at least degree + 1 (B-spline)"},
    {"width", "float", "1", "", "non-negative and finite", kPbrtV3, "width along the whole curve"},
    {"width0", "float", "(width)", "", "non-negative and finite", kPbrtV3,
     "width at the curve's start"},
    {"width1", "float", "(width)", "", "non-negative and finite", kPbrtV3,
     "width at the curve's end"},
    {"N", "normal3[]", "(none)", "", "", kPbrtV3, "ribbons only: one normal per segment end"},
    {"splitdepth", "integer", "3", "", "within [0, 12]", kPbrtV3,
     "each segment becomes 2^splitdepth pieces"},
};

const ShapePlugin kShapes[] = {
    {{"shape", "sphere", kAllDialects, "(partial) sphere about the origin (pbrt 2e §3.2)",
      kSphereParams},
     quadric<createSphereShape>},
    {{"shape", "cylinder", kAllDialects, "(partial) cylinder about the z axis (pbrt 2e §3.3)",
      kCylinderParams},
     quadric<createCylinderShape>},
    {{"shape", "disk", kAllDialects, "disk or ring facing +z (pbrt 2e §3.4)", kDiskParams},
     quadric<createDiskShape>},
    {{"shape", "cone", kAllDialects, "cone about the z axis, base at z = 0 (pbrt 2e §3.5.1)",
      kConeParams},
     quadric<createConeShape>},
    {{"shape", "paraboloid", kAllDialects, "paraboloid about the z axis (pbrt 2e §3.5.2)",
      kParaboloidParams},
     quadric<createParaboloidShape>},
    {{"shape", "hyperboloid", kAllDialects,
      "hyperboloid of revolution through the segment p1 p2, fitted as pbrt (pbrt 2e §3.5.3)",
      kHyperboloidParams},
     hyperboloid},
    {{"shape", "heightfield", kAllDialects,
      "heights over the unit square as a triangle mesh (pbrt-v2's; lrt draft App. C)",
      kHeightfieldParams},
     heightfield},
    {{"shape", "trianglemesh", kAllDialects, "triangle mesh (pbrt 2e §3.6)", kTriangleMeshParams},
     triangleMesh},
    {{"shape", "plymesh", kPbrtV3, "triangle mesh read from a PLY file (pbrt-v3's)",
      kPlyMeshParams},
     plyMesh},
    {{"shape", "loopsubdiv", kAllDialects,
      "Loop subdivision surface, refined once into a triangle mesh (pbrt 2e §3.7)",
      kLoopSubdivParams},
     loopSubdiv},
    {{"shape", "nurbs", kAllDialects,
      "NURBS surface diced into a triangle mesh (pbrt-v2's; lrt draft App. C)", kNurbsParams},
     nurbs},
    {{"shape", "curve", kPbrtV3, "Bézier or B-spline curve of some width (pbrt 3e §3.7)",
      kCurveParams},
     curve},
};

}  // namespace

std::span<const ShapePlugin> shapePlugins() { return kShapes; }

}  // namespace candela
