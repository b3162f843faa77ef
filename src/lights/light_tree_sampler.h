// "bvh" light sampling (pbrt-v4's default; Conty Estevez & Kulla 2018, pbrt 4e §12.6): a binary
// tree over the lights that have a position, each node holding the LightBounds of the lights
// below it. A point chooses a light by descending from the root, taking each child with
// probability in proportion to its importance at the point; its probability is the product of
// those choices. Lights at infinity (distant, infinite) have no bounds: together they are chosen
// as often as the whole tree, each with equal probability among them.
//
// The tree is built once, top down, splitting each node where Conty Estevez & Kulla's cost (power
// times orientation measure times surface area, on either side) is least over twelve buckets of
// the centroids along each axis; in the order of the lights given, so the same lights always make
// the same tree. Each leaf is one light.
#pragma once

#include <vector>

#include "lights/light_sampler.h"

namespace candela {

class LightTreeSampler final : public LightSampler {
 public:
  explicit LightTreeSampler(const std::vector<const Light*>& lights);

  const Light* sample(const LightSampleContext& at, Float u, Float* pmf) const override;
  Float pmf(const LightSampleContext& at, const Light& light) const override;

  // For tests and statistics.
  int nodeCount() const { return int(nodes_.size()); }
  int depth() const { return depth_; }
  int lightsAtInfinity() const { return int(atInfinity_.size()); }

 private:
  struct Node {
    LightBounds bounds;
    int parent = -1;
    int secondChild = -1;  // interior: the first child follows the node itself
    int light = -1;        // leaf: the light's index in lights_
    bool leaf() const { return light >= 0; }
  };
  struct Item {
    LightBounds bounds;
    Point3f centroid;
    int light;
  };
  int build(std::vector<Item>& items, size_t begin, size_t end, int parent, int depth);
  // The probability of choosing the tree rather than a light at infinity.
  double treeShare() const;

  std::vector<const Light*> lights_;
  LightIndex index_;
  std::vector<Node> nodes_;
  std::vector<int> leafOf_;         // per light: its leaf, or -1 (at infinity or without power)
  std::vector<int> atInfinity_;     // the lights' indices
  std::vector<int> infinityIndex_;  // per light: its place in atInfinity_, or -1
  int depth_ = 0;
};

}  // namespace candela
