// Axis-aligned boxes (lrt draft §2.6). The default box is empty (inverted), so a union with any
// point gives that point.
#pragma once

#include "core/vector.h"

namespace candela {

struct Bounds2i {
  Point2i pMin, pMax;  // half-open: [pMin, pMax)
  Bounds2i() = default;
  Bounds2i(Point2i a, Point2i b) : pMin(a), pMax(b) {}
  int area() const { return std::max(0, pMax.x - pMin.x) * std::max(0, pMax.y - pMin.y); }
  bool empty() const { return pMax.x <= pMin.x || pMax.y <= pMin.y; }
  bool inside(Point2i p) const {
    return p.x >= pMin.x && p.x < pMax.x && p.y >= pMin.y && p.y < pMax.y;
  }
  bool operator==(const Bounds2i& b) const { return pMin == b.pMin && pMax == b.pMax; }
};
inline Bounds2i intersect(const Bounds2i& a, const Bounds2i& b) {
  return Bounds2i(Point2i(std::max(a.pMin.x, b.pMin.x), std::max(a.pMin.y, b.pMin.y)),
                  Point2i(std::min(a.pMax.x, b.pMax.x), std::min(a.pMax.y, b.pMax.y)));
}

struct Bounds2f {
  Point2f pMin, pMax;
  Bounds2f() = default;
  Bounds2f(Point2f a, Point2f b) : pMin(a), pMax(b) {}
};

struct Bounds3f {
  Point3f pMin{kInfinity, kInfinity, kInfinity};
  Point3f pMax{-kInfinity, -kInfinity, -kInfinity};
  Bounds3f() = default;
  explicit Bounds3f(const Point3f& p) : pMin(p), pMax(p) {}
  Bounds3f(const Point3f& a, const Point3f& b) : pMin(min(a, b)), pMax(max(a, b)) {}
  const Point3f& operator[](int i) const { return i == 0 ? pMin : pMax; }
  bool empty() const { return pMax.x < pMin.x || pMax.y < pMin.y || pMax.z < pMin.z; }
  Vector3f diagonal() const { return pMax - pMin; }
  Point3f corner(int c) const {
    return {(*this)[c & 1].x, (*this)[(c & 2) ? 1 : 0].y, (*this)[(c & 4) ? 1 : 0].z};
  }
  Float surfaceArea() const {
    Vector3f d = diagonal();
    return 2 * (d.x * d.y + d.x * d.z + d.y * d.z);
  }
  int maximumExtent() const { return maxDimension(diagonal()); }
  bool inside(const Point3f& p) const {
    return p.x >= pMin.x && p.x <= pMax.x && p.y >= pMin.y && p.y <= pMax.y && p.z >= pMin.z &&
           p.z <= pMax.z;
  }
  void boundingSphere(Point3f* center, Float* radius) const {
    *center = (pMin + pMax) * 0.5f;
    *radius = inside(*center) ? distance(*center, pMax) : 0;
  }
};
inline Bounds3f unionOf(const Bounds3f& b, const Point3f& p) {
  Bounds3f r;
  r.pMin = min(b.pMin, p);
  r.pMax = max(b.pMax, p);
  return r;
}
inline Bounds3f unionOf(const Bounds3f& a, const Bounds3f& b) {
  Bounds3f r;
  r.pMin = min(a.pMin, b.pMin);
  r.pMax = max(a.pMax, b.pMax);
  return r;
}

}  // namespace candela
