// The uniform grid of the lrt draft (§4.3; seed 000 inventory §5): equal voxels over the scene
// bound, each listing the items its volume overlaps, walked front to back by a 3D-DDA
// (Amanatides-Woo) with mailboxing.
//
// Lazy refinement (the draft's refineimmediately = false) exists for primitives that cannot be
// intersected until they are refined into others (a subdivision surface, a whole mesh); a voxel
// refines them when a ray first enters it and swaps in a nested grid. Every primitive candela
// builds is already intersectable (meshes arrive as triangles; refinement happens in the shape
// factories), so nothing is left to refine at traversal time. What maps is the nested grid: each
// instanced prototype gets its own grid (built once, with the aggregate, and shared by all its
// instances), the draft's "GridAccel(p, true, false)" for a refined primitive. The parameter
// "refineimmediately" is accepted and changes nothing.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "accel/aggregate.h"
#include "accel/leaf_items.h"
#include "accel/scene_geometry.h"

namespace candela {

class GridAggregate : public Aggregate {
 public:
  // Static primitives (which must outlive the grid and stay in place).
  explicit GridAggregate(std::span<const Primitive> primitives);
  // Primitives and instances; prototypes get grids of their own.
  explicit GridAggregate(const SceneGeometry& geometry);

  Bounds3f worldBound() const override { return bounds_; }
  bool intersect(const Ray& ray, SurfaceInteraction* isect) const override;
  bool intersectP(const Ray& ray) const override;
  // counts: "voxels", "nonempty voxels", "references", "items", "instances", "prototypes",
  // "bytes".
  AggregateStats stats() const override;

  // The draft's resolution rule: 3 N^(1/3) voxels along the longest axis of bounds, the others
  // in proportion (voxels as close to cubes as the counts allow), each count in [1, 64].
  static std::array<int, 3> resolution(const Bounds3f& bounds, size_t nItems);
  const std::array<int, 3>& voxelCounts() const { return n_; }

 private:
  void build();
  int posToVoxel(Float p, int axis) const;
  Float voxelToPos(int v, int axis) const { return bounds_.pMin[axis] + v * width_[axis]; }
  // Calls visit(item) for each item of each voxel the ray crosses, front to back, until
  // visit returns true (a hit that ends the walk) or the walk passes ray.tMax.
  template <typename Visit>
  bool walk(const Ray& ray, Visit&& visit) const;

  LeafItems items_;
  Bounds3f bounds_;
  std::array<int, 3> n_ = {1, 1, 1};
  Vector3f width_, invWidth_;
  // Voxel v (x + nx (y + ny z)) lists items voxelItems_[voxelStart_[v] .. voxelStart_[v + 1]).
  std::vector<uint32_t> voxelStart_;
  std::vector<uint32_t> voxelItems_;
};

}  // namespace candela
