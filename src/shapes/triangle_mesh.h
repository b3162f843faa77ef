// Triangle meshes (lrt draft §3.6; watertight intersection and its error bounds pbrt 3e §3.6.2,
// §3.9.6). Vertices are transformed to world space once, at construction; each triangle is a
// small Shape that refers to its mesh. The Embree aggregate hands whole meshes to Embree as
// native triangles and calls interactionAt for the hit it reports.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/paramset.h"
#include "core/transform.h"
#include "shapes/shape.h"

namespace candela {

template <typename T>
class Texture;

struct TriangleMesh {
  // Positions, normals and tangents are given in object space. n (if given) is flipped when
  // reverseOrientation, so that ReverseOrientation turns smooth meshes around too (as pbrt 4e
  // does; pbrt 3e ignores it when a mesh has normals).
  TriangleMesh(const Transform& objectToWorld, bool reverseOrientation, std::vector<int> indices,
               std::vector<Point3f> p, std::vector<Normal3f> n = {}, std::vector<Vector3f> s = {},
               std::vector<Point2f> uv = {});
  int triangleCount() const { return int(indices.size() / 3); }

  std::vector<int> indices;  // 3 per triangle
  std::vector<Point3f> p;    // world space
  std::vector<Normal3f> n;   // world space, empty or one per vertex
  std::vector<Vector3f> s;   // world space, empty or one per vertex
  std::vector<Point2f> uv;   // empty or one per vertex
  bool reverseOrientation, transformSwapsHandedness;
  // Per triangle, made once from its world-space vertices: the unit normal of the winding,
  // (p0 - p2) x (p1 - p2) normalised ((0, 0, 1) when it has no length), and the area. Every hit,
  // light sample and light density needs them; 16 bytes a triangle save a cross product, a
  // square root and a division each time. (dp/du and dp/dv would save a hit about 3 % of a
  // render's instructions, but 24 bytes more a triangle: a 1M-triangle mesh grew 9 %.)
  struct Face {
    Normal3f n;
    Float area;
  };
  std::vector<Face> faces;
  // Cut-outs (pbrt-v2's "alpha" and "shadowalpha"): a hit where the texture is 0 at its (u, v)
  // is ignored, by intersect (alpha) and by intersectP (shadowAlpha). Owned by the scene's
  // textures; nullptr: opaque.
  const Texture<Float>* alpha = nullptr;
  const Texture<Float>* shadowAlpha = nullptr;
};

class TriangleShape : public Shape {
 public:
  TriangleShape(const TriangleMesh* mesh, int index) : mesh_(mesh), index_(index) {}

  Bounds3f worldBound() const override;
  // The watertight test: no ray slips between triangles sharing an edge, and hits closer than
  // the test's own error bound on t are rejected.
  bool intersect(const Ray& ray, Float* tHit, SurfaceInteraction* isect) const override;
  bool intersectP(const Ray& ray) const override;
  // The surface at barycentrics (b1, b2) (p = b0 p0 + b1 p1 + b2 p2, b0 = 1 - b1 - b2) hit at
  // ray parameter t: as used for the hits Embree reports (its u, v are b1, b2).
  SurfaceInteraction interactionAt(const Ray& ray, Float b1, Float b2, Float t) const;
  // The same, written into *isect.
  void interactionAt(const Ray& ray, Float b1, Float b2, Float /*t*/,
                     SurfaceInteraction* isect) const {
    interactionAt(*mesh_, index_, ray, b1, b2, isect);
  }
  // The same for triangle `index` of mesh, without its shape: for callers that know the mesh
  // (Embree's triangle geometries), whose hits then reach the vertices in fewer dependent loads.
  static void interactionAt(const TriangleMesh& mesh, int index, const Ray& ray, Float b1, Float b2,
                            SurfaceInteraction* isect);
  // Zero area (collinear or repeated vertices) or a NaN or infinite vertex: never hit.
  bool degenerate() const;
  // Whether the mesh's alpha (shadowAlpha when forShadow) cuts the hit (b1, b2, t) away.
  bool alphaCulls(const Ray& ray, Float b1, Float b2, Float t, bool forShadow) const;
  Float area() const override;
  // Uniform barycentrics; the normal oriented as an intersection's.
  Interaction sample(const Point2f& u, Float* pdf) const override;
  // Shape::sample(ref, ...)'s point and density, from one cross product for normal and area.
  Interaction sample(const Interaction& ref, const Point2f& u, Float* pdf) const override;
  // The same with the unit direction, from the distance the density was converted with.
  Interaction sampleFrom(const Interaction& ref, const Point2f& u, Float* pdf,
                         Vector3f* wi) const override;
  // Shape::pdf's density, from the triangle test alone (no interaction is made).
  Float pdf(const Interaction& ref, const Vector3f& wi) const override;
  const TriangleMesh* triangleMesh(int* triangleIndex) const override {
    if (triangleIndex) *triangleIndex = index_;
    return mesh_;
  }
  // The face normal as its interactions orient it, when that side is the same at every point.
  DirectionCone normalBound() const override;
  const char* kind() const override { return "triangle"; }

  const TriangleMesh* mesh() const { return mesh_; }
  int index() const { return index_; }

 private:
  // The geometric normal for the vertex winding, turned as the mesh says (interpolated normal
  // if any, else ReverseOrientation xor handedness swap); with its area when asked (both from the
  // mesh's faces).
  Normal3f orientedNormal(Float b0, Float b1, Float b2, Float* area = nullptr) const {
    return orientedNormal(*mesh_, index_, b0, b1, b2, area);
  }
  static Normal3f orientedNormal(const TriangleMesh& mesh, int index, Float b0, Float b1, Float b2,
                                 Float* area = nullptr);
  const int* v() const { return &mesh_->indices[3 * index_]; }
  // A point uniform by area with its normal, and the area.
  Interaction sampleArea(const Point2f& u, Float* area) const;

  const TriangleMesh* mesh_;
  int index_;
};

// One TriangleShape per triangle of mesh (which must outlive them).
std::vector<std::unique_ptr<Shape>> createTriangleShapes(const TriangleMesh* mesh);

// "trianglemesh": "indices" (integer, 3 per triangle; may be omitted for a single triangle),
// "P" (point3), optional "N" (normal), "S" (vector), "uv" or "st" (point2 or float pairs).
// Throws SceneError naming the offending parameter at its location.
std::vector<std::unique_ptr<Shape>> createTriangleMeshShapes(const Transform& objectToWorld,
                                                             bool reverseOrientation,
                                                             const ParamSet& params,
                                                             std::unique_ptr<TriangleMesh>* meshOut,
                                                             const FileLoc& loc);

// "plymesh": "filename" (relative paths are relative to baseDir). Throws SceneError at the
// filename's location when the file cannot be read or its contents are invalid.
std::vector<std::unique_ptr<Shape>> createPlyMeshShapes(
    const Transform& objectToWorld, bool reverseOrientation, const ParamSet& params,
    std::unique_ptr<TriangleMesh>* meshOut, const FileLoc& loc, const std::string& baseDir);

}  // namespace candela
