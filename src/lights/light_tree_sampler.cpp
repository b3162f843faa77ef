#include "lights/light_tree_sampler.h"

#include <algorithm>
#include <array>
#include <limits>

namespace candela {

namespace {

constexpr int kBuckets = 12;
// Past this depth nodes split at the median, so that no tree is deeper than this plus log2 of
// the number of lights (a path's choices are kept on the stack).
constexpr int kCostSplitDepth = 64;
constexpr int kMaxDepth = 128;

// The area term of the split cost; a flat or a degenerate group by its diagonal instead, so that
// groups of points or of collinear lights still prefer splits that separate them.
Float areaMeasure(const Bounds3f& b) {
  Float a = b.surfaceArea();
  return a > 0 ? a : b.diagonal().lengthSquared();
}

Float splitCost(const LightBounds& b) {
  return b.phi > 0 ? b.phi * orientationMeasure(b) * areaMeasure(b.bounds) : 0;
}

}  // namespace

LightTreeSampler::LightTreeSampler(const std::vector<const Light*>& lights)
    : lights_(lights),
      index_(lights),
      leafOf_(lights.size(), -1),
      infinityIndex_(lights.size(), -1) {
  std::vector<Item> items;
  for (size_t i = 0; i < lights_.size(); ++i) {
    std::optional<LightBounds> b = lights_[i]->bounds();
    if (!b) {
      infinityIndex_[i] = int(atInfinity_.size());
      atInfinity_.push_back(int(i));
    } else if (b->phi > 0 && !b->bounds.empty()) {
      items.push_back({*b, (b->bounds.pMin + b->bounds.pMax) * Float(0.5), int(i)});
    }
  }
  if (!items.empty()) build(items, 0, items.size(), -1, 1);
}

int LightTreeSampler::build(std::vector<Item>& items, size_t begin, size_t end, int parent,
                            int depth) {
  depth_ = std::max(depth_, depth);
  int node = int(nodes_.size());
  nodes_.emplace_back();
  nodes_[size_t(node)].parent = parent;
  if (end - begin == 1) {
    nodes_[size_t(node)].bounds = items[begin].bounds;
    nodes_[size_t(node)].light = items[begin].light;
    leafOf_[size_t(items[begin].light)] = node;
    return node;
  }
  LightBounds all;
  Bounds3f centroids;
  for (size_t i = begin; i < end; ++i) {
    all = unionOf(all, items[i].bounds);
    centroids = unionOf(centroids, items[i].centroid);
  }

  // The cheapest bucket boundary over the three axes; ties to the more even split.
  int bestAxis = -1, bestBucket = 0;
  Float bestCost = std::numeric_limits<Float>::infinity();
  size_t bestImbalance = end - begin;
  Vector3f extent = centroids.diagonal();
  Float widest = std::max({extent.x, extent.y, extent.z});
  // The bucket of a centroid along an axis of non-zero extent.
  auto bucketOf = [&](const Item& it, int axis) {
    int b = int(Float(kBuckets) * (it.centroid[axis] - centroids.pMin[axis]) / extent[axis]);
    return std::clamp(b, 0, kBuckets - 1);
  };
  for (int axis = 0; axis < 3 && depth < kCostSplitDepth; ++axis) {
    if (!(extent[axis] > 0)) continue;
    std::array<LightBounds, kBuckets> bucket{};
    std::array<size_t, kBuckets> count{};
    for (size_t i = begin; i < end; ++i) {
      int b = bucketOf(items[i], axis);
      bucket[size_t(b)] = unionOf(bucket[size_t(b)], items[i].bounds);
      ++count[size_t(b)];
    }
    // A thin group split across its thin side pays more (their regularisation).
    Float thinness = widest / extent[axis];
    for (int split = 1; split < kBuckets; ++split) {
      LightBounds below, above;
      size_t nBelow = 0, nAbove = 0;
      for (int b = 0; b < split; ++b)
        below = unionOf(below, bucket[size_t(b)]), nBelow += count[size_t(b)];
      for (int b = split; b < kBuckets; ++b)
        above = unionOf(above, bucket[size_t(b)]), nAbove += count[size_t(b)];
      if (nBelow == 0 || nAbove == 0) continue;
      Float cost = (splitCost(below) + splitCost(above)) * thinness;
      size_t imbalance = nBelow > nAbove ? nBelow - nAbove : nAbove - nBelow;
      if (cost < bestCost || (cost == bestCost && imbalance < bestImbalance)) {
        bestCost = cost;
        bestAxis = axis;
        bestBucket = split;
        bestImbalance = imbalance;
      }
    }
  }

  size_t mid;
  if (bestAxis >= 0) {
    auto below = [&](const Item& it) { return bucketOf(it, bestAxis) < bestBucket; };
    mid = size_t(
        std::stable_partition(items.begin() + long(begin), items.begin() + long(end), below) -
        items.begin());
  } else {
    // Every centroid in one place, or deep: halve by count along the widest axis (the lights'
    // order breaks ties, so the split is the same on every run).
    int axis = maxDimension(extent);
    mid = begin + (end - begin) / 2;
    std::nth_element(items.begin() + long(begin), items.begin() + long(mid),
                     items.begin() + long(end), [axis](const Item& a, const Item& b) {
                       if (a.centroid[axis] != b.centroid[axis])
                         return a.centroid[axis] < b.centroid[axis];
                       return a.light < b.light;
                     });
  }
  build(items, begin, mid, node, depth + 1);
  int second = build(items, mid, end, node, depth + 1);
  nodes_[size_t(node)].secondChild = second;
  nodes_[size_t(node)].bounds = all;
  return node;
}

double LightTreeSampler::treeShare() const {
  if (nodes_.empty()) return 0;
  return atInfinity_.empty() ? 1 : 1 / double(atInfinity_.size() + 1);
}

const Light* LightTreeSampler::sample(const LightSampleContext& at, Float u, Float* pmf) const {
  *pmf = 0;
  double tree = treeShare();
  double infinity = atInfinity_.empty() ? 0 : 1 - tree;
  if (u < infinity) {
    size_t n = atInfinity_.size();
    size_t i = std::min(size_t(double(u) / infinity * double(n)), n - 1);
    *pmf = Float(infinity / double(n));
    return lights_[size_t(atInfinity_[i])];
  }
  if (nodes_.empty()) return nullptr;
  double v = std::min(double(kOneMinusEpsilon), (double(u) - infinity) / tree);
  int node = 0;
  if (nodes_[0].leaf()) {
    if (!(nodes_[0].bounds.importance(at.p, at.n) > 0)) return nullptr;
    *pmf = Float(tree);
    return lights_[size_t(nodes_[0].light)];
  }
  // The choices' probabilities, multiplied leaf first below as pmf() does, to the same bits.
  std::array<double, kMaxDepth> choice;
  int depth = 0;
  while (!nodes_[size_t(node)].leaf()) {
    int first = node + 1, second = nodes_[size_t(node)].secondChild;
    double a = nodes_[size_t(first)].bounds.importance(at.p, at.n);
    double b = nodes_[size_t(second)].bounds.importance(at.p, at.n);
    if (!(a + b > 0)) return nullptr;
    double pFirst = a / (a + b);
    if (v < pFirst) {
      v = std::min(double(kOneMinusEpsilon), v / pFirst);
      choice[size_t(depth++)] = pFirst;
      node = first;
    } else {
      v = std::min(double(kOneMinusEpsilon), (v - pFirst) / (1 - pFirst));
      choice[size_t(depth++)] = b / (a + b);
      node = second;
    }
  }
  double p = 1;
  while (depth > 0) p *= choice[size_t(--depth)];
  *pmf = Float(tree * p);
  return lights_[size_t(nodes_[size_t(node)].light)];
}

Float LightTreeSampler::pmf(const LightSampleContext& at, const Light& light) const {
  int i = index_.of(light);
  if (i < 0) return 0;
  if (infinityIndex_[size_t(i)] >= 0) return Float((1 - treeShare()) / double(atInfinity_.size()));
  int node = leafOf_[size_t(i)];
  if (node < 0) return 0;
  double tree = treeShare();
  if (node == 0) return nodes_[0].bounds.importance(at.p, at.n) > 0 ? Float(tree) : 0;
  double p = 1;
  while (nodes_[size_t(node)].parent >= 0) {
    int parent = nodes_[size_t(node)].parent;
    int first = parent + 1, second = nodes_[size_t(parent)].secondChild;
    double a = nodes_[size_t(first)].bounds.importance(at.p, at.n);
    double b = nodes_[size_t(second)].bounds.importance(at.p, at.n);
    double mine = node == first ? a : b;
    if (!(mine > 0)) return 0;
    p *= mine / (a + b);
    node = parent;
  }
  return Float(tree * p);
}

}  // namespace candela
