// Ray preliminaries shared by the reference aggregates (grid, kd-tree, BVH): which rays are
// traced at all, and a conservative, NaN-safe ray-box slab test (lrt draft §4.2 / seed 000
// inventory §23; the rounding bound is pbrt 3e §3.9.2).
#pragma once

#include <cmath>

#include "core/bounds.h"
#include "core/ray.h"

namespace candela {

// Rays every aggregate answers with a miss, as the Embree aggregate does: NaN or infinite origin
// or direction components, a zero direction, a NaN or non-positive tMax. tMax = +inf is fine.
inline bool isTraceableRay(const Ray& ray) {
  return std::isfinite(ray.o.x) && std::isfinite(ray.o.y) && std::isfinite(ray.o.z) &&
         std::isfinite(ray.d.x) && std::isfinite(ray.d.y) && std::isfinite(ray.d.z) &&
         (ray.d.x != 0 || ray.d.y != 0 || ray.d.z != 0) && ray.tMax > 0;
}

// Per-ray constants of the slab test. A zero direction component gives an infinite reciprocal
// (IEEE: 1/+0 = +inf, 1/-0 = -inf), so that slab is either never left or never entered.
struct RaySlabs {
  Point3f o;
  Vector3f invDir;
  int dirIsNeg[3];
  explicit RaySlabs(const Ray& ray) : o(ray.o) {
    invDir = Vector3f(1 / ray.d.x, 1 / ray.d.y, 1 / ray.d.z);
    dirIsNeg[0] = invDir.x < 0;
    dirIsNeg[1] = invDir.y < 0;
    dirIsNeg[2] = invDir.z < 0;
  }
};

// Widens a computed slab exit so that the interval contains the exact one: each slab distance
// carries at most three roundings, so (1 + 2 gamma(3)) covers both ends (pbrt 3e §3.9.2).
inline constexpr Float kSlabExitScale = 1 + 2 * gamma(3);

// The parametric range [*t0, *t1] of the ray inside b, clipped to [tMin, tMax]; false when empty.
// When the origin lies in a slab's plane and that direction component is zero, (p - o) * inv is
// 0 * inf = NaN; the comparisons below are written so that a NaN never replaces t0 or t1 (the
// draft's "t0 = tNear > t0 ? tNear : t0", inventory §23): such a ray is inside that slab. A ray
// parallel to a slab and below it gets tNear = tFar = +inf, which with tMax = +inf would pass
// "t0 <= t1"; an infinite entry is therefore a miss.
inline bool clipToBox(const Bounds3f& b, const RaySlabs& r, Float tMin, Float tMax, Float* t0,
                      Float* t1) {
  Float lo = tMin, hi = tMax;
  for (int a = 0; a < 3; ++a) {
    Float tNear = (b.pMin[a] - r.o[a]) * r.invDir[a];
    Float tFar = (b.pMax[a] - r.o[a]) * r.invDir[a];
    if (tNear > tFar) std::swap(tNear, tFar);
    tFar *= kSlabExitScale;
    lo = tNear > lo ? tNear : lo;
    hi = tFar < hi ? tFar : hi;
    if (lo > hi) return false;
  }
  if (lo == kInfinity) return false;
  *t0 = lo;
  *t1 = hi;
  return true;
}

// The same test written for speed with the precomputed signs (BVH traversal): true when the
// ray's [0, tMax] range meets b. NaNs from 0 * inf fail every comparison and are ignored.
inline bool hitsBox(const Bounds3f& b, const RaySlabs& r, Float tMax) {
  Float lo = 0, hi = tMax;
  const Point3f* corner[2] = {&b.pMin, &b.pMax};
  for (int a = 0; a < 3; ++a) {
    Float tNear = ((*corner[r.dirIsNeg[a]])[a] - r.o[a]) * r.invDir[a];
    Float tFar = ((*corner[1 - r.dirIsNeg[a]])[a] - r.o[a]) * r.invDir[a] * kSlabExitScale;
    lo = tNear > lo ? tNear : lo;
    hi = tFar < hi ? tFar : hi;
  }
  return lo <= hi && lo < kInfinity;
}

// A bound padded by a few ulps of its coordinates' magnitude: a shape's floating-point test may
// report a hit a few ulps outside its float bound (a grazing ray at a sphere's tangent plane, a
// triangle edge on the box face), and the aggregates must still visit it then.
inline Bounds3f padBound(const Bounds3f& b) {
  if (b.empty()) return b;
  Bounds3f r = b;
  for (int a = 0; a < 3; ++a) {
    Float m = std::max(std::abs(b.pMin[a]), std::abs(b.pMax[a]));
    Float pad = 4 * gamma(3) * m;
    r.pMin[a] = nextFloatDown(b.pMin[a] - pad);
    r.pMax[a] = nextFloatUp(b.pMax[a] + pad);
  }
  return r;
}

}  // namespace candela
