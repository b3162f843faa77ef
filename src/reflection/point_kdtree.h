// A static kd-tree over points in R^D answering k-nearest-neighbour and fixed-radius queries, for
// looking up irregularly sampled measured BRDFs (pbrt 2e §8.6: every sample within a radius) and
// photons (pbrt 2e §15.6: the k nearest within a maximum distance, optionally only those a
// predicate accepts).
// The tree is implicit: each range of the index permutation stores its median at the middle, down
// to small leaf ranges.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "core/common.h"

namespace candela {

template <int D>
class PointKdTree {
 public:
  using Point = std::array<Float, D>;

  PointKdTree() = default;
  explicit PointKdTree(std::vector<Point> points) : points_(std::move(points)) {
    order_.resize(points_.size());
    axis_.resize(points_.size());
    for (size_t i = 0; i < order_.size(); ++i) order_[i] = uint32_t(i);
    build(0, int(order_.size()));
    // Store the points in tree order so that a search walks memory mostly forwards.
    std::vector<Point> sorted(points_.size());
    for (size_t i = 0; i < order_.size(); ++i) sorted[i] = points_[order_[i]];
    points_ = std::move(sorted);
  }
  size_t size() const { return points_.size(); }
  size_t memoryBytes() const {
    return points_.capacity() * sizeof(Point) + order_.capacity() * sizeof(uint32_t) +
           axis_.capacity() * sizeof(uint8_t);
  }

  // The up to k nearest points to q: their indices (in construction order) and squared
  // distances, nearest first. Returns how many were found (min(k, size())).
  int nearest(const Point& q, int k, uint32_t* indices, Float* dist2) const {
    return nearestWithin(q, k, kInfinity, indices, dist2);
  }
  // The same among the points strictly closer than sqrt(maxDist2).
  int nearestWithin(const Point& q, int k, Float maxDist2, uint32_t* indices, Float* dist2) const {
    return nearestMatching(
        q, k, maxDist2, [](uint32_t) { return true; }, indices, dist2);
  }
  // The same among the points whose construction index `accept` returns true for.
  template <typename Accept>
  int nearestMatching(const Point& q, int k, Float maxDist2, const Accept& accept,
                      uint32_t* indices, Float* dist2) const {
    Query<Accept> query{q, k, maxDist2, accept, indices, dist2, 0};
    Point off;
    off.fill(0);
    if (k > 0) search(0, int(order_.size()), query, 0, off);
    return query.found;
  }

  // Calls visit(index, dist2) for every point strictly closer than sqrt(maxDist2), index in
  // construction order. The order of the calls depends only on the tree and q, so sums over them
  // are reproducible.
  template <typename Visit>
  void forEachWithin(const Point& q, Float maxDist2, const Visit& visit) const {
    visitWithin(0, int(order_.size()), q, maxDist2, visit);
  }

 private:
  static Float distance2(const Point& a, const Point& b) {
    Float d = 0;
    for (int i = 0; i < D; ++i) d += (a[i] - b[i]) * (a[i] - b[i]);
    return d;
  }

  // Ranges this small are leaves, scanned linearly: cheaper than recursing to single points.
  static constexpr int kLeafSize = 8;

  void build(int lo, int hi) {
    if (hi - lo <= kLeafSize) return;
    // Split on the axis of largest extent.
    Point lower, upper;
    lower.fill(kInfinity);
    upper.fill(-kInfinity);
    for (int i = lo; i < hi; ++i)
      for (int a = 0; a < D; ++a) {
        lower[a] = std::min(lower[a], points_[order_[i]][a]);
        upper[a] = std::max(upper[a], points_[order_[i]][a]);
      }
    int axis = 0;
    for (int a = 1; a < D; ++a)
      if (upper[a] - lower[a] > upper[axis] - lower[axis]) axis = a;
    int mid = (lo + hi) / 2;
    std::nth_element(order_.begin() + lo, order_.begin() + mid, order_.begin() + hi,
                     [&](uint32_t a, uint32_t b) { return points_[a][axis] < points_[b][axis]; });
    axis_[mid] = uint8_t(axis);
    build(lo, mid);
    build(mid + 1, hi);
  }

  template <typename Accept>
  struct Query {
    const Point& q;
    int k;
    Float maxDist2;
    const Accept& accept;
    uint32_t* indices;
    Float* dist2;
    int found;
    // Squared distance a candidate must beat: the k-th best so far, else the search radius.
    Float bound() const { return found == k ? std::min(dist2[k - 1], maxDist2) : maxDist2; }
  };

  // Keeps the k best in ascending order of distance (k is small: insertion is enough).
  template <typename Accept>
  static void insert(uint32_t index, Float d2, Query<Accept>& qr) {
    if (!(d2 < qr.bound()) || !qr.accept(index)) return;
    int i = qr.found < qr.k ? qr.found++ : qr.k - 1;
    while (i > 0 && qr.dist2[i - 1] > d2) {
      qr.dist2[i] = qr.dist2[i - 1];
      qr.indices[i] = qr.indices[i - 1];
      --i;
    }
    qr.dist2[i] = d2;
    qr.indices[i] = index;
  }

  // rd is the squared distance from q to the current range's cell, kept incrementally from the
  // per-axis offsets off (Arya and Mount 1993): a far cell is pruned by its box, not only by its
  // splitting plane, which matters in more than two or three dimensions.
  template <typename Accept>
  void search(int lo, int hi, Query<Accept>& qr, Float rd, Point& off) const {
    if (hi - lo <= kLeafSize) {
      for (int i = lo; i < hi; ++i) insert(order_[i], distance2(qr.q, points_[i]), qr);
      return;
    }
    int mid = (lo + hi) / 2;
    insert(order_[mid], distance2(qr.q, points_[mid]), qr);
    int axis = axis_[mid];
    Float diff = qr.q[axis] - points_[mid][axis];
    int nearLo = diff < 0 ? lo : mid + 1, nearHi = diff < 0 ? mid : hi;
    int farLo = diff < 0 ? mid + 1 : lo, farHi = diff < 0 ? hi : mid;
    search(nearLo, nearHi, qr, rd, off);
    Float old = off[axis];
    Float farRd = rd - old * old + diff * diff;
    if (farRd < qr.bound()) {
      off[axis] = diff;
      search(farLo, farHi, qr, farRd, off);
      off[axis] = old;
    }
  }

  template <typename Visit>
  void visitWithin(int lo, int hi, const Point& q, Float maxDist2, const Visit& visit) const {
    if (hi - lo <= kLeafSize) {
      for (int i = lo; i < hi; ++i)
        if (Float d2 = distance2(q, points_[i]); d2 < maxDist2) visit(order_[i], d2);
      return;
    }
    int mid = (lo + hi) / 2;
    if (Float d2 = distance2(q, points_[mid]); d2 < maxDist2) visit(order_[mid], d2);
    Float diff = q[axis_[mid]] - points_[mid][axis_[mid]];
    // The lower half lies at or below the splitting plane, the upper half at or above it.
    if (diff <= 0 || diff * diff < maxDist2) visitWithin(lo, mid, q, maxDist2, visit);
    if (diff >= 0 || diff * diff < maxDist2) visitWithin(mid + 1, hi, q, maxDist2, visit);
  }

  std::vector<Point> points_;
  std::vector<uint32_t> order_;
  std::vector<uint8_t> axis_;
};

}  // namespace candela
