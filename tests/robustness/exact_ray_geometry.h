// Exact answers for robustness tests of ray intersection: the float ray and the float shape as
// stored, evaluated in long double (64-bit significand: products of floats are exact, and the
// sums here lose far less than a float step), and a fixed-seed generator of long double
// directions.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>

#include "core/ray.h"

namespace candela::test::exact {

using Real = long double;
struct Vec {
  Real x, y, z;
};
inline Vec operator-(Vec a, Vec b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec operator+(Vec a, Vec b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec operator*(Vec a, Real s) { return {a.x * s, a.y * s, a.z * s}; }
inline Real dot(Vec a, Vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec cross(Vec a, Vec b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline Real length(Vec a) { return std::sqrt(dot(a, a)); }
inline Vec unit(Vec a) { return a * (1 / length(a)); }
inline Vec of(const Point3f& p) { return {p.x, p.y, p.z}; }
inline Vec of(const Vector3f& v) { return {v.x, v.y, v.z}; }
inline Point3f toPoint(Vec a) { return Point3f(Float(a.x), Float(a.y), Float(a.z)); }
inline Vector3f toVector(Vec a) { return Vector3f(Float(a.x), Float(a.y), Float(a.z)); }

// Uniform long doubles and directions from a fixed-seed generator (bits, not library
// distributions).
struct Random {
  std::mt19937_64 bits;
  explicit Random(uint64_t seed) : bits(seed) {}
  Real uniform() { return Real(bits() >> 11) * 0x1p-53L; }
  Vec direction() {
    Real z = 1 - 2 * uniform(), phi = 2 * 3.14159265358979323846L * uniform();
    Real r = std::sqrt(std::max(Real(0), 1 - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
  }
  Vec perpendicularTo(Vec d) {
    for (;;) {
      Vec c = cross(d, direction());
      if (length(c) > 0.1L) return unit(c);
    }
  }
};

// The distance between the line o + t d and the segment from a to b: the squared distance of
// a + s (b - a) from the line is a convex quadratic in s, least at its unconstrained minimum
// clamped to [0, 1].
inline Real lineSegmentDistance(Vec o, Vec d, Vec a, Vec b) {
  Vec u = cross(a - o, d), w = cross(b - a, d);
  Real ww = dot(w, w), s = ww > 0 ? std::clamp(-dot(u, w) / ww, Real(0), Real(1)) : 0;
  return length(u + w * s) / length(d);
}

struct TriangleTruth {
  // How far the line passes inside (> 0) or outside (< 0) the triangle's boundary: the distance
  // from the line to the nearest edge segment, in float steps at the coordinates' magnitude.
  Real gapSteps;
  Real t;     // where the line meets the plane
  Real b[3];  // the barycentrics of that point
  Vec x;      // the point
  Real step;  // the float step at the coordinates' magnitude
};

// The exact answer for the float ray against the float triangle (x = b0 v0 + b1 v1 + b2 v2): the
// line passes inside when the three signed volumes d . ((a - o) x (b - o)) over the edges (a, b)
// have the sign of d . n (they sum to it, and each over the sum is a barycentric). Steps are
// measured at the largest coordinate of the vertices and the origin.
inline TriangleTruth truth(const std::array<Point3f, 3>& v, const Ray& ray) {
  Vec o = of(ray.o), d = of(ray.d), p[3] = {of(v[0]), of(v[1]), of(v[2])};
  Vec n = cross(p[1] - p[0], p[2] - p[0]);
  Real dn = dot(d, n), distance = 1e30L, magnitude = 0;
  TriangleTruth r;
  bool inside = true;
  for (int k = 0; k < 3; ++k) {
    Vec a = p[(k + 1) % 3], b = p[(k + 2) % 3];
    r.b[k] = dot(d, cross(a - o, b - o)) / dn;
    inside = inside && r.b[k] > 0;
    distance = std::min(distance, lineSegmentDistance(o, d, a, b));
    for (Real c : {p[k].x, p[k].y, p[k].z}) magnitude = std::max(magnitude, std::abs(c));
  }
  for (Real c : {o.x, o.y, o.z}) magnitude = std::max(magnitude, std::abs(c));
  r.step = std::ldexp(Real(1), std::ilogb(double(magnitude)) - 23);
  r.gapSteps = (inside ? distance : -distance) / r.step;
  r.t = dot(n, p[0] - o) / dn;
  r.x = o + d * r.t;
  return r;
}

}  // namespace candela::test::exact
