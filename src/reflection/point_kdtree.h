// A static kd-tree over points in R^D answering k-nearest-neighbour queries, for looking up
// irregularly sampled measured BRDFs (pbrt-v2's "measured" material keeps its samples in one).
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

  // The up to k nearest points to q: their indices (in construction order) and squared
  // distances, nearest first. Returns how many were found (min(k, size())).
  int nearest(const Point& q, int k, uint32_t* indices, Float* dist2) const {
    int found = 0;
    Point off;
    off.fill(0);
    if (k > 0) search(0, int(order_.size()), q, 0, off, k, indices, dist2, &found);
    return found;
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

  // Keeps the k best in ascending order of distance (k is small: insertion is enough).
  static void insert(uint32_t index, Float d2, int k, uint32_t* indices, Float* dist2, int* found) {
    if (*found == k && d2 >= dist2[k - 1]) return;
    int i = *found < k ? (*found)++ : k - 1;
    while (i > 0 && dist2[i - 1] > d2) {
      dist2[i] = dist2[i - 1];
      indices[i] = indices[i - 1];
      --i;
    }
    dist2[i] = d2;
    indices[i] = index;
  }

  // rd is the squared distance from q to the current range's cell, kept incrementally from the
  // per-axis offsets off (Arya and Mount 1993): a far cell is pruned by its box, not only by its
  // splitting plane, which matters in more than two or three dimensions.
  void search(int lo, int hi, const Point& q, Float rd, Point& off, int k, uint32_t* indices,
              Float* dist2, int* found) const {
    if (hi - lo <= kLeafSize) {
      for (int i = lo; i < hi; ++i)
        insert(order_[i], distance2(q, points_[i]), k, indices, dist2, found);
      return;
    }
    int mid = (lo + hi) / 2;
    insert(order_[mid], distance2(q, points_[mid]), k, indices, dist2, found);
    int axis = axis_[mid];
    Float diff = q[axis] - points_[mid][axis];
    int nearLo = diff < 0 ? lo : mid + 1, nearHi = diff < 0 ? mid : hi;
    int farLo = diff < 0 ? mid + 1 : lo, farHi = diff < 0 ? hi : mid;
    search(nearLo, nearHi, q, rd, off, k, indices, dist2, found);
    Float old = off[axis];
    Float farRd = rd - old * old + diff * diff;
    if (*found < k || farRd < dist2[k - 1]) {
      off[axis] = diff;
      search(farLo, farHi, q, farRd, off, k, indices, dist2, found);
      off[axis] = old;
    }
  }

  std::vector<Point> points_;
  std::vector<uint32_t> order_;
  std::vector<uint8_t> axis_;
};

}  // namespace candela
