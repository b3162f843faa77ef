#include "accel/kdtree/kdtree_aggregate.h"

#include <algorithm>
#include <cmath>

#include "accel/mailbox.h"
#include "accel/ray_query.h"

namespace candela {

int KdTreeAggregate::depthLimit(size_t nItems, int maxDepthParam) {
  int d = maxDepthParam;
  if (d <= 0) d = int(std::lround(8 + 1.3 * log2Int(uint32_t(std::max<size_t>(nItems, 1)))));
  return std::min(d, kMaxDepth);
}

// The recursive SAH build (lrt draft §4.4.2). Item lists live on one stack vector: a node pushes
// its children's lists, builds the below child (which pushes and pops above them), then the
// above child, then pops both, so only the lists along the current path are ever held.
struct KdTreeAggregate::Builder {
  // A start or end of an item's bound along one axis; code = item << 1 | isEnd.
  struct Edge {
    Float t;
    uint32_t code;
    uint32_t item() const { return code >> 1; }
    bool isEnd() const { return code & 1; }
    // Starts before ends at equal t, so a split there leaves a flat item in one child only.
    bool operator<(const Edge& e) const { return t < e.t || (t == e.t && code % 2 < e.code % 2); }
  };

  KdTreeAggregate& tree;
  const KdTreeParams& params;
  std::vector<Bounds3f> itemBounds;
  std::vector<Edge> edges[3];
  std::vector<uint32_t> lists;

  void makeLeaf(uint32_t node, size_t begin, uint32_t n) {
    Node& nd = tree.nodes_[node];
    nd.bits = (n << 2) | 3;
    nd.itemsOffset = 0;
    if (n == 1) {
      nd.oneItem = lists[begin];
    } else if (n > 1) {
      nd.itemsOffset = uint32_t(tree.leafItems_.size());
      tree.leafItems_.insert(tree.leafItems_.end(), lists.begin() + long(begin),
                             lists.begin() + long(begin + n));
    }
  }

  void sortEdges(int axis, size_t begin, uint32_t n) {
    std::vector<Edge>& e = edges[axis];
    for (uint32_t k = 0; k < n; ++k) {
      uint32_t item = lists[begin + k];
      const Bounds3f& b = itemBounds[item];
      e[2 * k] = Edge{b.pMin[axis], item << 1};
      e[2 * k + 1] = Edge{b.pMax[axis], (item << 1) | 1};
    }
    std::sort(e.begin(), e.begin() + 2 * long(n));
  }

  void build(size_t begin, uint32_t n, const Bounds3f& nodeBounds, int depthLeft, int depth,
             int badRefines) {
    uint32_t node = uint32_t(tree.nodes_.size());
    tree.nodes_.push_back(Node{});
    tree.maxDepthReached_ = std::max(tree.maxDepthReached_, depth);
    if (n <= uint32_t(params.maxPrims) || depthLeft == 0) {
      makeLeaf(node, begin, n);
      return;
    }

    // The cost of a split at t: a traversal step plus the items on each side, weighted by the
    // chance that a ray through the node passes through that side (its share of the node's
    // surface area), discounted by the empty bonus when one side holds nothing.
    Float leafCost = Float(params.intersectCost) * Float(n);
    Vector3f d = nodeBounds.diagonal();
    Float invTotalArea = 1 / nodeBounds.surfaceArea();
    Float bestCost = kInfinity;
    int bestAxis = -1;
    uint32_t bestEdge = 0;
    int axis = nodeBounds.maximumExtent();
    for (int tries = 0; tries < 3 && bestAxis == -1; ++tries, axis = (axis + 1) % 3) {
      sortEdges(axis, begin, n);
      int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
      Float capArea = d[a1] * d[a2], girth = d[a1] + d[a2];
      uint32_t nBelow = 0, nAbove = n;
      for (uint32_t i = 0; i < 2 * n; ++i) {
        const Edge& e = edges[axis][i];
        if (e.isEnd()) --nAbove;
        if (e.t > nodeBounds.pMin[axis] && e.t < nodeBounds.pMax[axis]) {
          Float pBelow = 2 * (capArea + (e.t - nodeBounds.pMin[axis]) * girth) * invTotalArea;
          Float pAbove = 2 * (capArea + (nodeBounds.pMax[axis] - e.t) * girth) * invTotalArea;
          Float bonus = (nBelow == 0 || nAbove == 0) ? params.emptyBonus : 0;
          Float cost =
              Float(params.traversalCost) + Float(params.intersectCost) * (1 - bonus) *
                                                (pBelow * Float(nBelow) + pAbove * Float(nAbove));
          if (cost < bestCost) {
            bestCost = cost;
            bestAxis = axis;
            bestEdge = i;
          }
        }
        if (!e.isEnd()) ++nBelow;
      }
    }
    // A few splits worse than a leaf are allowed on a path (later ones may pay off); a much
    // worse one with few items, no candidate at all, or the third bad one makes a leaf.
    if (bestCost > leafCost) ++badRefines;
    if ((bestCost > 4 * leafCost && n < 16) || bestAxis == -1 || badRefines == 3) {
      makeLeaf(node, begin, n);
      return;
    }

    // Items starting before the split edge go below, items ending after it go above; an item
    // straddling the plane goes to both.
    const std::vector<Edge>& e = edges[bestAxis];
    size_t belowBegin = lists.size();
    for (uint32_t i = 0; i < bestEdge; ++i)
      if (!e[i].isEnd()) lists.push_back(e[i].item());
    uint32_t nBelow = uint32_t(lists.size() - belowBegin);
    size_t aboveBegin = lists.size();
    for (uint32_t i = bestEdge + 1; i < 2 * n; ++i)
      if (e[i].isEnd()) lists.push_back(e[i].item());
    uint32_t nAbove = uint32_t(lists.size() - aboveBegin);
    Float split = e[bestEdge].t;

    Bounds3f below = nodeBounds, above = nodeBounds;
    below.pMax[bestAxis] = split;
    above.pMin[bestAxis] = split;
    build(belowBegin, nBelow, below, depthLeft - 1, depth + 1, badRefines);
    uint32_t aboveIndex = uint32_t(tree.nodes_.size());
    tree.nodes_[node].split = split;
    tree.nodes_[node].bits = (aboveIndex << 2) | uint32_t(bestAxis);
    build(aboveBegin, nAbove, above, depthLeft - 1, depth + 1, badRefines);
    lists.resize(belowBegin);
  }
};

KdTreeAggregate::KdTreeAggregate(std::span<const Primitive> primitives, const KdTreeParams& params)
    : params_(params), items_(primitives) {
  build();
}

KdTreeAggregate::KdTreeAggregate(const SceneGeometry& geometry, const KdTreeParams& params)
    : params_(params), items_(geometry, [params](std::span<const Primitive> prims) {
        return std::make_unique<KdTreeAggregate>(prims, params);
      }) {
  build();
}

void KdTreeAggregate::build() {
  Builder b{*this, params_, {}, {}, {}};
  uint32_t count = items_.size();
  b.itemBounds.resize(count);
  for (uint32_t i = 0; i < count; ++i) {
    b.itemBounds[i] = items_.bound(i);
    if (b.itemBounds[i].empty()) continue;
    bounds_ = unionOf(bounds_, b.itemBounds[i]);
    b.lists.push_back(i);
  }
  uint32_t n = uint32_t(b.lists.size());
  if (n == 0) return;
  for (auto& e : b.edges) e.resize(2 * size_t(n));
  b.build(0, n, bounds_, depthLimit(n, params_.maxDepth), 0, 0);
  nodes_.shrink_to_fit();
  leafItems_.shrink_to_fit();
}

// Front-to-back traversal (lrt draft §4.4.3): at each split the child on the origin's side comes
// first; the far child is visited only if the ray reaches the plane within the node's range.
template <typename LeafTest>
bool KdTreeAggregate::traverse(const Ray& ray, LeafTest&& leafTest) const {
  RaySlabs slabs(ray);
  Float tMin, tMax;
  if (nodes_.empty() || !clipToBox(bounds_, slabs, 0, ray.tMax, &tMin, &tMax)) return false;
  struct Todo {
    uint32_t node;
    Float tMin, tMax;
  };
  Todo todo[kMaxDepth + 2];  // one entry per level at most
  int nTodo = 0;
  uint32_t node = 0;
  for (;;) {
    // A node that starts past the closest hit so far holds nothing closer.
    if (!(ray.tMax < tMin)) {
      const Node& nd = nodes_[node];
      if (!nd.isLeaf()) {
        int a = nd.axis();
        Float o = ray.o[a], split = nd.split;
        uint32_t below = node + 1, above = nd.aboveChild();
        if (ray.d[a] == 0) {
          // Parallel to the plane: only the origin's side, or both when the ray lies in it.
          if (o == split) todo[nTodo++] = Todo{above, tMin, tMax};
          node = o <= split ? below : above;
          continue;
        }
        bool belowFirst = o < split || (o == split && ray.d[a] < 0);
        uint32_t first = belowFirst ? below : above, second = belowFirst ? above : below;
        // The plane distance has three roundings (1/d, split - o, the product); its sign is
        // exact. Near and far ranges overlap by that bound.
        Float tPlane = (split - o) * slabs.invDir[a];
        Float slack = std::abs(tPlane) * gamma(3);
        if (tPlane <= 0 || tPlane - slack > tMax) {
          node = first;
        } else if (tPlane + slack < tMin) {
          node = second;
        } else {
          todo[nTodo++] = Todo{second, std::max(tMin, tPlane - slack), tMax};
          node = first;
          tMax = std::min(tMax, tPlane + slack);
        }
        continue;
      }
      if (leafTest(nd)) return true;
    }
    if (nTodo == 0) return false;
    --nTodo;
    node = todo[nTodo].node;
    tMin = todo[nTodo].tMin;
    tMax = todo[nTodo].tMax;
  }
}

bool KdTreeAggregate::intersect(const Ray& ray, SurfaceInteraction* isect) const {
  if (!isTraceableRay(ray)) return false;
  RayMailbox mailbox;
  bool hit = false;
  auto test = [&](uint32_t item) {
    if (!mailbox.testedBefore(item) && items_.intersect(item, ray, isect)) hit = true;
  };
  traverse(ray, [&](const Node& leaf) {
    uint32_t n = leaf.count();
    if (n == 1) test(leaf.oneItem);
    for (uint32_t k = 0; n > 1 && k < n; ++k) test(leafItems_[leaf.itemsOffset + k]);
    return false;  // later nodes may still hold a closer hit
  });
  return hit;
}

bool KdTreeAggregate::intersectP(const Ray& ray) const {
  if (!isTraceableRay(ray)) return false;
  RayMailbox mailbox;
  auto test = [&](uint32_t item) {
    return !mailbox.testedBefore(item) && items_.intersectP(item, ray);
  };
  return traverse(ray, [&](const Node& leaf) {
    uint32_t n = leaf.count();
    if (n == 1) return test(leaf.oneItem);
    for (uint32_t k = 0; k < n; ++k)
      if (test(leafItems_[leaf.itemsOffset + k])) return true;
    return false;
  });
}

AggregateStats KdTreeAggregate::stats() const {
  AggregateStats s;
  s.name = "kdtree";
  long leaves = 0, empty = 0, refs = 0;
  for (const Node& n : nodes_) {
    if (!n.isLeaf()) continue;
    ++leaves;
    empty += n.count() == 0;
    refs += n.count();
  }
  s.counts["nodes"] = long(nodes_.size());
  s.counts["leaves"] = leaves;
  s.counts["empty leaves"] = empty;
  s.counts["max depth"] = maxDepthReached_;
  s.counts["references"] = refs;
  s.counts["items"] = long(items_.size());
  s.counts["instances"] = items_.instanceCount();
  s.counts["prototypes"] = items_.prototypeCount();
  s.counts["bytes"] = long(sizeof(*this) + nodes_.capacity() * sizeof(Node) +
                           leafItems_.capacity() * sizeof(uint32_t)) +
                      items_.bytes();
  return s;
}

}  // namespace candela
