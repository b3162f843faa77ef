// Rays and ray differentials (lrt draft §2.5). Directions need not be unit length.
#pragma once

#include "core/vector.h"

namespace candela {

struct Ray {
  Point3f o;
  Vector3f d;
  mutable Float tMax = kInfinity;
  Float time = 0;
  Ray() = default;
  Ray(const Point3f& o_, const Vector3f& d_, Float tMax_ = kInfinity, Float time_ = 0)
      : o(o_), d(d_), tMax(tMax_), time(time_) {}
  Point3f operator()(Float t) const { return o + d * t; }
  bool hasNaN() const { return o.hasNaN() || d.hasNaN() || std::isnan(tMax); }
};

// Rays are traced only from and along points of at most 1.844e18 in every coordinate: Embree
// asserts beyond that (its FLT_LARGE), finite or not. Rays outside the range miss everything, and
// cameras that would make them are refused.
constexpr Float kLargestTraceableCoordinate = 1.844e18f;
inline bool withinTraceableRange(const Point3f& o, const Vector3f& d) {
  for (int i = 0; i < 3; ++i)
    if (!(std::abs(o[i]) <= kLargestTraceableCoordinate) ||
        !(std::abs(d[i]) <= kLargestTraceableCoordinate))
      return false;
  return true;
}

// A camera ray plus two rays offset by one pixel in x and y, for texture filtering.
struct RayDifferential : Ray {
  bool hasDifferentials = false;
  Point3f rxOrigin, ryOrigin;
  Vector3f rxDirection, ryDirection;
  RayDifferential() = default;
  RayDifferential(const Point3f& o_, const Vector3f& d_, Float tMax_ = kInfinity, Float time_ = 0)
      : Ray(o_, d_, tMax_, time_) {}
  explicit RayDifferential(const Ray& r) : Ray(r) {}
  // The main ray with the rays one pixel over in x and y as its differentials.
  RayDifferential(const Ray& r, const Ray& rx, const Ray& ry)
      : Ray(r),
        hasDifferentials(true),
        rxOrigin(rx.o),
        ryOrigin(ry.o),
        rxDirection(rx.d),
        ryDirection(ry.d) {}
  void scaleDifferentials(Float s) {
    rxOrigin = o + (rxOrigin - o) * s;
    ryOrigin = o + (ryOrigin - o) * s;
    rxDirection = d + (rxDirection - d) * s;
    ryDirection = d + (ryDirection - d) * s;
  }
};

// Moves p off a surface along n by its floating-point error bound, on the side w points to, so
// that a ray from there cannot re-hit the surface it left (pbrt 3e §3.9.5).
inline Point3f offsetRayOrigin(const Point3f& p, const Vector3f& pError, const Normal3f& n,
                               const Vector3f& w) {
  Float d = dot(abs(Vector3f(n)), pError);
  Vector3f offset = Vector3f(n) * d;
  if (dot(w, n) < 0) offset = -offset;
  Point3f po = p + offset;
  for (int i = 0; i < 3; ++i) {
    if (offset[i] > 0)
      po[i] = nextFloatUp(po[i]);
    else if (offset[i] < 0)
      po[i] = nextFloatDown(po[i]);
  }
  return po;
}

}  // namespace candela
