// The kd-tree of the lrt draft (§4.4; seed 000 inventory §5): axis-aligned splits chosen by the
// surface area heuristic over the items' bound edges, 8-byte nodes in one array (below child
// next to its parent, above child by index), front-to-back traversal with a fixed-size stack.
//
// Differences from the draft, each for a stated reason:
// - If no split candidate lies inside the node on the longest axis, the other two axes are tried
//   before giving up (pbrt-v2): a node long in x whose items all span it in x can still be cut
//   in y or z.
// - The split position is a whole float; the axis and counts live in the other word (the draft
//   overwrites the split's two low mantissa bits with the axis, moving the plane).
// - Traversal widens each split distance by its rounding bound, so a ray within rounding of a
//   split plane visits both sides (the draft can drop an item that touches the plane).
// - Mailboxing uses a per-query cache (accel/mailbox.h), safe with many threads.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "accel/aggregate.h"
#include "accel/leaf_items.h"
#include "accel/scene_geometry.h"

namespace candela {

// The draft's parameters and defaults ("Accelerator "kdtree"", App. C.3.7). pbrt-v2 uses
// emptybonus 0.5; the draft's 0.2 is kept.
struct KdTreeParams {
  int intersectCost = 80;
  int traversalCost = 1;
  Float emptyBonus = 0.2f;
  int maxPrims = 1;
  int maxDepth = -1;  // <= 0: round(8 + 1.3 log2 N)
};

class KdTreeAggregate : public Aggregate {
 public:
  explicit KdTreeAggregate(std::span<const Primitive> primitives, const KdTreeParams& params = {});
  explicit KdTreeAggregate(const SceneGeometry& geometry, const KdTreeParams& params = {});

  Bounds3f worldBound() const override { return bounds_; }
  bool intersect(const Ray& ray, SurfaceInteraction* isect) const override;
  bool intersectP(const Ray& ray) const override;
  // counts: "nodes", "leaves", "empty leaves", "max depth", "references", "items",
  // "instances", "prototypes", "bytes".
  AggregateStats stats() const override;

  // The depth limit used for n items: maxDepthParam if positive, else the draft's
  // round(8 + 1.3 log2 n); either way at most kMaxDepth.
  static int depthLimit(size_t nItems, int maxDepthParam);
  // The traversal stack holds one entry per level, so the depth is capped below its size.
  static constexpr int kMaxDepth = 62;

 private:
  // 8 bytes. bits: low 2 = split axis (0, 1, 2) or 3 for a leaf; high 30 = above child's index
  // (interior) or item count (leaf). The first word is the split position (interior), the item
  // (leaf of one) or an offset into leafItems_ (larger leaves).
  struct Node {
    union {
      Float split;
      uint32_t oneItem;
      uint32_t itemsOffset;
    };
    uint32_t bits;
    bool isLeaf() const { return (bits & 3) == 3; }
    int axis() const { return int(bits & 3); }
    uint32_t count() const { return bits >> 2; }       // leaf
    uint32_t aboveChild() const { return bits >> 2; }  // interior
  };
  struct Builder;
  void build();
  template <typename LeafTest>
  bool traverse(const Ray& ray, LeafTest&& leafTest) const;

  KdTreeParams params_;
  LeafItems items_;
  Bounds3f bounds_;
  std::vector<Node> nodes_;
  std::vector<uint32_t> leafItems_;  // item lists of leaves holding more than one
  int maxDepthReached_ = 0;
};

}  // namespace candela
