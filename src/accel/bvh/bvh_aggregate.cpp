#include "accel/bvh/bvh_aggregate.h"

#include <algorithm>
#include <limits>

#include "accel/ray_query.h"

namespace candela {

namespace {
constexpr int kBuckets = 12;
// Costs relative to one item intersection: a node visit (a box test) is taken as 1/8 of it.
constexpr Float kTraversalCost = 0.125f;
constexpr uint32_t kMaxLeafCount = std::numeric_limits<uint16_t>::max();
}  // namespace

struct BvhAggregate::Builder {
  struct Item {
    Bounds3f bounds;
    Point3f centroid;
    uint32_t index;
  };
  BvhAggregate& bvh;
  std::vector<Item> items;

  uint32_t makeLeaf(uint32_t node, size_t begin, size_t end) {
    Node& nd = bvh.nodes_[node];
    nd.offset = uint32_t(bvh.itemOrder_.size());
    nd.count = uint16_t(end - begin);
    for (size_t i = begin; i < end; ++i) bvh.itemOrder_.push_back(items[i].index);
    return node;
  }

  // Splits [begin, end) in two halves of equal count by centroid along axis; returns the middle.
  size_t splitEqual(size_t begin, size_t end, int axis) {
    size_t mid = (begin + end) / 2;
    std::nth_element(
        items.begin() + long(begin), items.begin() + long(mid), items.begin() + long(end),
        [axis](const Item& a, const Item& b) { return a.centroid[axis] < b.centroid[axis]; });
    return mid;
  }

  // The binned SAH split (pbrt 2e §4.4.2): the cost of a split is the traversal step plus each
  // side's item count weighted by its bound's share of the node's surface area (the chance that
  // a ray through the node enters it). Returns the middle, or begin when a leaf is cheaper.
  size_t splitSah(size_t begin, size_t end, int axis, const Bounds3f& bounds,
                  const Bounds3f& centroids) {
    size_t n = end - begin;
    Float lo = centroids.pMin[axis], extent = centroids.pMax[axis] - lo;
    auto bucketOf = [&](const Item& it) {
      int b = int(kBuckets * ((it.centroid[axis] - lo) / extent));
      return clamp(b, 0, kBuckets - 1);
    };
    Bounds3f bucketBounds[kBuckets];
    size_t bucketCount[kBuckets] = {};
    for (size_t i = begin; i < end; ++i) {
      int b = bucketOf(items[i]);
      ++bucketCount[b];
      bucketBounds[b] = unionOf(bucketBounds[b], items[i].bounds);
    }
    // Sweeps from each end give every split's two sides in linear time.
    Float rightArea[kBuckets];
    size_t rightCount[kBuckets];
    Bounds3f acc;
    size_t count = 0;
    for (int b = kBuckets - 1; b > 0; --b) {
      acc = unionOf(acc, bucketBounds[b]);
      count += bucketCount[b];
      rightArea[b] = acc.empty() ? 0 : acc.surfaceArea();
      rightCount[b] = count;
    }
    Float invArea = 1 / bounds.surfaceArea();
    Float bestCost = kInfinity;
    int bestSplit = -1;  // the split after bucket bestSplit
    acc = Bounds3f();
    count = 0;
    for (int b = 0; b + 1 < kBuckets; ++b) {
      acc = unionOf(acc, bucketBounds[b]);
      count += bucketCount[b];
      if (count == 0 || rightCount[b + 1] == 0) continue;
      Float cost = kTraversalCost + (Float(count) * acc.surfaceArea() +
                                     Float(rightCount[b + 1]) * rightArea[b + 1]) *
                                        invArea;
      if (cost < bestCost) {
        bestCost = cost;
        bestSplit = b;
      }
    }
    if (bestSplit < 0) return splitEqual(begin, end, axis);
    bool leafAllowed = n <= size_t(bvh.params_.maxNodePrims);
    if (leafAllowed && !(bestCost < Float(n))) return begin;
    auto mid = std::partition(items.begin() + long(begin), items.begin() + long(end),
                              [&](const Item& it) { return bucketOf(it) <= bestSplit; });
    return size_t(mid - items.begin());
  }

  uint32_t build(size_t begin, size_t end, int depth) {
    uint32_t node = uint32_t(bvh.nodes_.size());
    bvh.nodes_.push_back(Node{});
    bvh.maxDepthReached_ = std::max(bvh.maxDepthReached_, depth);
    Bounds3f bounds, centroids;
    for (size_t i = begin; i < end; ++i) {
      bounds = unionOf(bounds, items[i].bounds);
      centroids = unionOf(centroids, items[i].centroid);
    }
    bvh.nodes_[node].bounds = bounds;
    size_t n = end - begin;
    if (n == 1) return makeLeaf(node, begin, end);

    int axis = centroids.maximumExtent();
    size_t mid;
    if (!(centroids.pMax[axis] > centroids.pMin[axis]) || !(bounds.surfaceArea() > 0)) {
      // Every centroid at one point (or no area to weigh): no split separates anything, so a
      // leaf, unless it would hold more than a leaf can count.
      if (n <= kMaxLeafCount) return makeLeaf(node, begin, end);
      mid = begin + n / 2;
    } else if (depth >= kEqualSplitDepth || bvh.params_.splitMethod == BvhSplitMethod::Equal) {
      if (n <= size_t(bvh.params_.maxNodePrims)) return makeLeaf(node, begin, end);
      mid = splitEqual(begin, end, axis);
    } else if (bvh.params_.splitMethod == BvhSplitMethod::Middle) {
      if (n <= size_t(bvh.params_.maxNodePrims)) return makeLeaf(node, begin, end);
      Float m = (centroids.pMin[axis] + centroids.pMax[axis]) / 2;
      auto it = std::partition(items.begin() + long(begin), items.begin() + long(end),
                               [&](const Item& x) { return x.centroid[axis] < m; });
      mid = size_t(it - items.begin());
      if (mid == begin || mid == end) mid = splitEqual(begin, end, axis);
    } else {
      mid = splitSah(begin, end, axis, bounds, centroids);
      if (mid == begin) return makeLeaf(node, begin, end);
    }
    bvh.nodes_[node].axis = uint8_t(axis);
    build(begin, mid, depth + 1);
    uint32_t second = build(mid, end, depth + 1);
    bvh.nodes_[node].offset = second;
    return node;
  }
};

BvhAggregate::BvhAggregate(std::span<const Primitive> primitives, const BvhParams& params)
    : params_(params), items_(primitives) {
  build();
}

BvhAggregate::BvhAggregate(const SceneGeometry& geometry, const BvhParams& params)
    : params_(params), items_(geometry, [params](std::span<const Primitive> prims) {
        return std::make_unique<BvhAggregate>(prims, params);
      }) {
  build();
}

void BvhAggregate::build() {
  params_.maxNodePrims = clamp(params_.maxNodePrims, 1, int(kMaxLeafCount));
  Builder b{*this, {}};
  uint32_t count = items_.size();
  b.items.reserve(count);
  for (uint32_t i = 0; i < count; ++i) {
    Bounds3f bound = items_.bound(i);
    if (!bound.empty()) b.items.push_back({bound, (bound.pMin + bound.pMax) * 0.5f, i});
  }
  if (b.items.empty()) return;
  nodes_.reserve(2 * b.items.size());
  itemOrder_.reserve(b.items.size());
  b.build(0, b.items.size(), 0);
  nodes_.shrink_to_fit();
}

template <typename LeafTest>
bool BvhAggregate::traverse(const Ray& ray, LeafTest&& leafTest) const {
  if (nodes_.empty()) return false;
  RaySlabs slabs(ray);
  uint32_t todo[kStackSize];
  int nTodo = 0;
  uint32_t node = 0;
  for (;;) {
    const Node& nd = nodes_[node];
    // ray.tMax shrinks with each hit, so boxes beyond the closest hit so far are skipped.
    if (hitsBox(nd.bounds, slabs, ray.tMax)) {
      if (nd.count == 0) {
        // The child on the side the ray comes from first; the other waits on the stack.
        if (slabs.dirIsNeg[nd.axis]) {
          todo[nTodo++] = node + 1;
          node = nd.offset;
        } else {
          todo[nTodo++] = nd.offset;
          node = node + 1;
        }
        continue;
      }
      if (leafTest(nd)) return true;
    }
    if (nTodo == 0) return false;
    node = todo[--nTodo];
  }
}

bool BvhAggregate::intersect(const Ray& ray, SurfaceInteraction* isect) const {
  if (!isTraceableRay(ray)) return false;
  bool hit = false;
  traverse(ray, [&](const Node& leaf) {
    for (uint32_t k = 0; k < leaf.count; ++k)
      if (items_.intersect(itemOrder_[leaf.offset + k], ray, isect)) hit = true;
    return false;
  });
  return hit;
}

bool BvhAggregate::intersectP(const Ray& ray) const {
  if (!isTraceableRay(ray)) return false;
  return traverse(ray, [&](const Node& leaf) {
    for (uint32_t k = 0; k < leaf.count; ++k)
      if (items_.intersectP(itemOrder_[leaf.offset + k], ray)) return true;
    return false;
  });
}

AggregateStats BvhAggregate::stats() const {
  AggregateStats s;
  s.name = "bvh";
  long leaves = 0;
  for (const Node& n : nodes_) leaves += n.count > 0;
  s.counts["nodes"] = long(nodes_.size());
  s.counts["leaves"] = leaves;
  s.counts["max depth"] = maxDepthReached_;
  s.counts["items"] = long(items_.size());
  s.counts["instances"] = items_.instanceCount();
  s.counts["prototypes"] = items_.prototypeCount();
  s.counts["bytes"] = long(sizeof(*this) + nodes_.capacity() * sizeof(Node) +
                           itemOrder_.capacity() * sizeof(uint32_t)) +
                      items_.bytes();
  return s;
}

}  // namespace candela
