// Test helper: measures of 2D point sets in [0,1)^2 for the samplers' tests: the (0,k,2)-net
// property in base 2, the star discrepancy and the smallest distance on the unit torus.
#pragma once

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>
#include <vector>

#include "core/vector.h"

namespace candela::test {

// Whether 2^k points are a (0,k,2)-net in base 2: every elementary interval
// [a/2^i, (a+1)/2^i) x [b/2^j, (b+1)/2^j) with i + j = k holds exactly one point. With 2^k
// points and 2^k intervals of each shape, "one each" is "no interval holds two".
inline bool isZeroNet(const std::vector<Point2f>& points, int k) {
  if (points.size() != (size_t(1) << k)) return false;
  for (int i = 0; i <= k; ++i) {
    const int j = k - i;
    std::set<std::pair<long, long>> hit;
    for (const Point2f& p : points)
      hit.insert({long(std::floor(std::ldexp(double(p.x), i))),
                  long(std::floor(std::ldexp(double(p.y), j)))});
    if (hit.size() != points.size()) return false;
  }
  return true;
}

// Whether n values put one in each interval [a/n, (a+1)/n).
inline bool isStratified1D(const std::vector<Float>& values) {
  std::set<long> hit;
  for (Float v : values) hit.insert(long(std::floor(double(v) * double(values.size()))));
  return hit.size() == values.size();
}

// The star discrepancy sup over boxes [0,x) x [0,y) of |#points inside / n - x y|, exactly: the
// supremum is reached with x and y at point coordinates or 1, the box taken open or closed
// (Niederreiter 1992, §2.1). O(n^3), for n up to a few hundred.
inline double starDiscrepancy(const std::vector<Point2f>& points) {
  const double n = double(points.size());
  std::vector<double> xs{1.0}, ys{1.0};
  for (const Point2f& p : points) {
    xs.push_back(p.x);
    ys.push_back(p.y);
  }
  double d = 0;
  for (double x : xs)
    for (double y : ys) {
      int open = 0, closed = 0;
      for (const Point2f& p : points) {
        if (p.x < x && p.y < y) ++open;
        if (p.x <= x && p.y <= y) ++closed;
      }
      d = std::max({d, x * y - open / n, closed / n - x * y});
    }
  return d;
}

// The smallest distance between two of the points on the unit torus (coordinates wrap at 1).
inline double toroidalMinDistance(const std::vector<Point2f>& points) {
  double best = 2;
  for (size_t a = 0; a < points.size(); ++a)
    for (size_t b = a + 1; b < points.size(); ++b) {
      double dx = std::abs(double(points[a].x) - points[b].x);
      double dy = std::abs(double(points[a].y) - points[b].y);
      dx = std::min(dx, 1 - dx);
      dy = std::min(dy, 1 - dy);
      best = std::min(best, std::sqrt(dx * dx + dy * dy));
    }
  return best;
}

}  // namespace candela::test
