// A bounding volume hierarchy, the default accelerator of pbrt-v2 ("Accelerator "bvh""; pbrt 2e
// §4.4): items are split recursively into two groups by their bound centroids, each node keeping
// the bound of its group; the tree is stored flattened, depth first, in 32-byte nodes (first child
// next to its parent, second child by index) and walked with a small stack, nearer child first.
//
// Split methods ("splitmethod"):
// - "sah" (default): the surface area heuristic evaluated at the boundaries of 12 equal buckets
//   along the widest axis of the centroids (binned SAH), so a build is O(N log N);
// - "middle": at the midpoint of the centroids' extent (falling back to "equal" when one side
//   would be empty);
// - "equal": at the median, two halves of equal count.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "accel/aggregate.h"
#include "accel/leaf_items.h"
#include "accel/scene_geometry.h"

namespace candela {

enum class BvhSplitMethod { Sah, Middle, Equal };

struct BvhParams {
  int maxNodePrims = 4;  // pbrt-v2's "maxnodeprims"
  BvhSplitMethod splitMethod = BvhSplitMethod::Sah;
};

class BvhAggregate : public Aggregate {
 public:
  explicit BvhAggregate(std::span<const Primitive> primitives, const BvhParams& params = {});
  explicit BvhAggregate(const SceneGeometry& geometry, const BvhParams& params = {});

  Bounds3f worldBound() const override { return nodes_.empty() ? Bounds3f() : nodes_[0].bounds; }
  bool intersect(const Ray& ray, SurfaceInteraction* isect) const override;
  bool intersectP(const Ray& ray) const override;
  // counts: "nodes", "leaves", "max depth", "items", "instances", "prototypes", "bytes".
  AggregateStats stats() const override;

  // Below this depth every split is "equal" (halving the count), so the depth stays under
  // kStackSize whatever the items' distribution.
  static constexpr int kEqualSplitDepth = 56;
  static constexpr int kStackSize = 96;

 private:
  struct Node {
    Bounds3f bounds;
    uint32_t offset;  // leaf: first entry in itemOrder_; interior: index of the second child
    uint16_t count;   // leaf: number of items (> 0); interior: 0
    uint8_t axis;     // interior: the split axis, for choosing the nearer child
    uint8_t pad = 0;
  };
  struct Builder;
  void build();
  template <typename LeafTest>
  bool traverse(const Ray& ray, LeafTest&& leafTest) const;

  BvhParams params_;
  LeafItems items_;
  std::vector<Node> nodes_;
  std::vector<uint32_t> itemOrder_;  // items in leaf order
  int maxDepthReached_ = 0;
};

}  // namespace candela
