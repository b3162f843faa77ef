// Path guiding's SD-tree (Müller, Gross & Novák 2017, "Practical Path Guiding", §3): a binary tree
// over space, split at the midpoint along x, y, z in turn, whose leaves each hold a directional
// distribution of incident radiance (DirectionalQuadtree). Trained in passes of doubling sample
// counts: a leaf that received more than splitFactor · sqrt(2^k) records in pass k is split, its
// halves starting from copies of its distribution (§3.4). Everything between passes is done in a
// fixed order and every record is an order-independent sum, so the field after a pass is the same
// bits for any number of threads and any tiling.
#pragma once

#include <atomic>
#include <vector>

#include "core/bounds.h"
#include "transport/directional_quadtree.h"

namespace candela {

class GuidingField {
 public:
  static constexpr double kDefaultSplitFactor = 12000;  // Müller's c
  static constexpr int kMaxSpatialDepth = 60;

  // bounds: the scene's; the tree's root is the cube around them, a little larger.
  explicit GuidingField(const Bounds3f& bounds, double splitFactor = kDefaultSplitFactor);
  GuidingField(const GuidingField&) = delete;
  GuidingField& operator=(const GuidingField&) = delete;

  // The leaf distribution at p (any point: outside the bounds, the nearest leaf's).
  const DirectionalQuadtree& at(const Point3f& p) const { return leaves_[leafIndex(p)].directions; }
  // Records an incident radiance estimate at p from w, divided by w's density (see
  // DirectionalQuadtree::record). Thread-safe.
  void record(const Point3f& p, const Vector3f& w, double value);
  // After pass number `pass` (0, 1, ...): the recorded radiance becomes the distribution, and
  // leaves that saw many records are split. Not concurrently with record or at.
  void finishPass(int pass);

  int leaves() const { return int(leaves_.size()); }
  int passesFinished() const { return passes_; }

 private:
  struct Node {
    // Inner node: children (indices into nodes_), split at the midpoint of axis depth % 3.
    // Leaf: child[0] == 0 and leaf indexes leaves_.
    uint32_t child[2] = {0, 0};
    uint32_t leaf = 0;
  };
  struct Leaf {
    DirectionalQuadtree directions;
    std::atomic<uint64_t> records{0};
    Leaf() = default;
    Leaf(const Leaf& o)
        : directions(o.directions), records(o.records.load(std::memory_order_relaxed)) {}
  };
  uint32_t leafIndex(const Point3f& p) const;
  // Splits the leaf at node while its estimated record count passes threshold.
  void split(uint32_t node, int depth, uint64_t records, double threshold);

  Point3f origin_;
  Float size_;
  double splitFactor_;
  std::vector<Node> nodes_;
  std::vector<Leaf> leaves_;
  int passes_ = 0;
};

}  // namespace candela
