// A static kd-tree over points in R^D answering k-nearest-neighbour queries, for looking up
// irregularly sampled measured BRDFs (pbrt-v2's "measured" material keeps its samples in one).
// The tree is implicit: each range of the index permutation stores its median at the middle.
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
  }
  size_t size() const { return points_.size(); }
  const Point& point(size_t i) const { return points_[i]; }

  // The up to k nearest points to q: their indices (in construction order) and squared
  // distances, nearest first. Returns how many were found (min(k, size())).
  int nearest(const Point& q, int k, uint32_t* indices, Float* dist2) const {
    int found = 0;
    if (k > 0) search(0, int(order_.size()), q, k, indices, dist2, &found);
    return found;
  }

 private:
  static Float distance2(const Point& a, const Point& b) {
    Float d = 0;
    for (int i = 0; i < D; ++i) d += (a[i] - b[i]) * (a[i] - b[i]);
    return d;
  }

  void build(int lo, int hi) {
    if (hi - lo < 1) return;
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

  void search(int lo, int hi, const Point& q, int k, uint32_t* indices, Float* dist2,
              int* found) const {
    if (hi <= lo) return;
    int mid = (lo + hi) / 2;
    uint32_t p = order_[mid];
    insert(p, distance2(q, points_[p]), k, indices, dist2, found);
    int axis = axis_[mid];
    Float diff = q[axis] - points_[p][axis];
    if (diff < 0) {
      search(lo, mid, q, k, indices, dist2, found);
      if (*found < k || diff * diff < dist2[k - 1])
        search(mid + 1, hi, q, k, indices, dist2, found);
    } else {
      search(mid + 1, hi, q, k, indices, dist2, found);
      if (*found < k || diff * diff < dist2[k - 1]) search(lo, mid, q, k, indices, dist2, found);
    }
  }

  std::vector<Point> points_;
  std::vector<uint32_t> order_;
  std::vector<uint8_t> axis_;
};

}  // namespace candela
