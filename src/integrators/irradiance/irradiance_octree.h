// The octree that holds irradiance samples (lrt draft appendix A.5; pbrt 2e §A.7): each sample
// is stored in the nodes its sphere of validity overlaps, at the depth where the node is about
// the sphere's size, so a lookup visits the one node per level that contains the point. Samples
// are kept in insertion order; a lookup visits them in an order fixed by the insertions alone.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/bounds.h"
#include "integrators/irradiance/irradiance_sample.h"

namespace candela {

class IrradianceOctree {
 public:
  // bounds must hold every point later looked up; points outside are found in no node.
  explicit IrradianceOctree(const Bounds3f& bounds);
  void add(const IrradianceSample& sample);
  // Calls visit(sample) for every sample whose stored extent may contain p.
  template <typename Visit>
  void forEachNear(const Point3f& p, Visit&& visit) const {
    if (!bounds_.inside(p)) return;
    const Node* node = &root_;
    Bounds3f b = bounds_;
    for (;;) {
      for (uint32_t i : node->samples) visit(samples_[i]);
      int child = childIndex(b, p);
      if (!node->children[child]) return;
      b = childBounds(b, child);
      node = node->children[child].get();
    }
  }
  const Bounds3f& bounds() const { return bounds_; }
  size_t size() const { return samples_.size(); }
  const std::vector<IrradianceSample>& samples() const { return samples_; }
  // Bytes held by the samples, the nodes and their index lists.
  size_t memoryBytes() const;

 private:
  struct Node {
    std::array<std::unique_ptr<Node>, 8> children;
    std::vector<uint32_t> samples;
  };
  static int childIndex(const Bounds3f& b, const Point3f& p);
  static Bounds3f childBounds(const Bounds3f& b, int child);
  void addTo(Node& node, const Bounds3f& nodeBounds, uint32_t index, const Bounds3f& extent,
             int depth);

  Bounds3f bounds_;
  Node root_;
  std::vector<IrradianceSample> samples_;
  size_t nodes_ = 1, references_ = 0;
};

}  // namespace candela
