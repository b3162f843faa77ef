#include "transport/guiding_field.h"

#include <algorithm>
#include <cmath>

namespace candela {

GuidingField::GuidingField(const Bounds3f& bounds, double splitFactor)
    : splitFactor_(splitFactor), nodes_(1), leaves_(1) {
  // A cube, so that splitting in turn along x, y and z keeps leaves near cubes (§3.4).
  Bounds3f b = bounds.empty() ? Bounds3f(Point3f(-1, -1, -1), Point3f(1, 1, 1)) : bounds;
  Vector3f d = b.diagonal();
  Float side = std::max({d.x, d.y, d.z, Float(1e-3)});
  Point3f center = (b.pMin + b.pMax) * Float(0.5);
  size_ = side * Float(1.01);
  origin_ = center - Vector3f(size_, size_, size_) * Float(0.5);
}

uint32_t GuidingField::leafIndex(const Point3f& p) const {
  // The point in the root cube's unit coordinates; each level doubles them about the midpoint.
  Float u[3] = {(p.x - origin_.x) / size_, (p.y - origin_.y) / size_, (p.z - origin_.z) / size_};
  uint32_t node = 0;
  for (int depth = 0; nodes_[node].child[0] != 0; ++depth) {
    Float& c = u[depth % 3];
    int side = c >= Float(0.5);
    c = 2 * c - Float(side);
    node = nodes_[node].child[side];
  }
  return nodes_[node].leaf;
}

void GuidingField::record(const Point3f& p, const Vector3f& w, double value) {
  Leaf& leaf = leaves_[leafIndex(p)];
  leaf.records.fetch_add(1, std::memory_order_relaxed);
  leaf.directions.record(w, value);
}

void GuidingField::split(uint32_t node, int depth, uint64_t records, double threshold) {
  if (double(records) <= threshold || depth >= kMaxSpatialDepth) return;
  uint32_t leaf = nodes_[node].leaf;
  uint32_t a = uint32_t(nodes_.size());
  nodes_.emplace_back();
  nodes_.emplace_back();
  nodes_[node].child[0] = a;
  nodes_[node].child[1] = a + 1;
  // The halves start from the leaf's distribution; the first keeps its slot.
  nodes_[a].leaf = leaf;
  nodes_[a + 1].leaf = uint32_t(leaves_.size());
  Leaf copy(leaves_[leaf]);
  leaves_.push_back(copy);
  // Each half is taken to have seen half the records (Müller's assumption).
  split(a, depth + 1, records / 2, threshold);
  split(a + 1, depth + 1, records / 2, threshold);
}

void GuidingField::finishPass(int pass) {
  // Distributions first (a split copies the learned one), in leaf order.
  for (Leaf& leaf : leaves_) leaf.directions.finishPass();
  const double threshold = splitFactor_ * std::sqrt(std::ldexp(1.0, pass));
  // The leaves as they are now, by node, in node order; splitting appends nodes and leaves.
  std::vector<std::pair<uint32_t, int>> leafNodes;  // node, depth
  std::vector<std::pair<uint32_t, int>> stack{{0, 0}};
  while (!stack.empty()) {
    auto [n, depth] = stack.back();
    stack.pop_back();
    if (nodes_[n].child[0] == 0) {
      leafNodes.push_back({n, depth});
    } else {
      stack.push_back({nodes_[n].child[1], depth + 1});
      stack.push_back({nodes_[n].child[0], depth + 1});
    }
  }
  for (auto [n, depth] : leafNodes) {
    uint64_t records = leaves_[nodes_[n].leaf].records.load(std::memory_order_relaxed);
    split(n, depth, records, threshold);
  }
  for (Leaf& leaf : leaves_) leaf.records.store(0, std::memory_order_relaxed);
  ++passes_;
}

}  // namespace candela
