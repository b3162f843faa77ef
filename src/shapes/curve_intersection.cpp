#include "shapes/curve_intersection.h"

#include <algorithm>
#include <cmath>

#include "shapes/curve_shape.h"

namespace candela {

namespace {

struct D3 {
  double x = 0, y = 0, z = 0;
};
D3 operator-(const D3& a, const D3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
D3 operator+(const D3& a, const D3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
D3 operator*(const D3& a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(const D3& a, const D3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
D3 mix(double t, const D3& a, const D3& b) { return a * (1 - t) + b * t; }
D3 toD3(const Vector3f& v) { return {v.x, v.y, v.z}; }

// Control points in the ray's frame: origin at the ray origin, z along the unit direction.
using Quad = D3[4];

void halve(const Quad& q, Quad& a, Quad& b) {
  D3 m01 = mix(0.5, q[0], q[1]), m12 = mix(0.5, q[1], q[2]), m23 = mix(0.5, q[2], q[3]);
  D3 l = mix(0.5, m01, m12), r = mix(0.5, m12, m23), mid = mix(0.5, l, r);
  a[0] = q[0], a[1] = m01, a[2] = l, a[3] = mid;
  b[0] = mid, b[1] = r, b[2] = m23, b[3] = q[3];
}

D3 evaluate(const Quad& q, double u) {
  D3 a = mix(u, q[0], q[1]), b = mix(u, q[1], q[2]), c = mix(u, q[2], q[3]);
  return mix(u, mix(u, a, b), mix(u, b, c));
}

// The smaller and larger real roots of a z^2 + 2 b z + c (a linear equation when a is 0).
int solveQuadratic(double a, double b, double c, double roots[2]) {
  if (a == 0) {
    if (b == 0) return 0;
    roots[0] = -c / (2 * b);
    return 1;
  }
  double disc = b * b - a * c;
  if (disc < 0) return 0;
  // The root without cancellation first, the other from the product c / a.
  double q = -(b + std::copysign(std::sqrt(disc), b));
  double r0 = q / a, r1 = q != 0 ? c / q : -b / a;
  roots[0] = std::min(r0, r1);
  roots[1] = std::max(r0, r1);
  return 2;
}

class PieceIntersector {
 public:
  // The ray's frame in world space (z along the ray), and how far along it to look.
  PieceIntersector(const CurveShape& shape, const D3& ex, const D3& ey, const D3& ez, double zMax)
      : shape_(shape), ex_(ex), ey_(ey), ez_(ez), zBest_(zMax) {}

  void recurse(const Quad& q, double s0, double s1, int depth) {
    if (!boundMeetsRay(q, s0, s1)) return;
    if (depth > 0) {
      Quad a, b;
      halve(q, a, b);
      double sm = 0.5 * (s0 + s1);
      recurse(a, s0, sm, depth - 1);
      recurse(b, sm, s1, depth - 1);
      return;
    }
    if (shape_.piece().type == CurveType::Cylinder)
      roundLeaf(q, s0, s1);
    else
      stripLeaf(q, s0, s1);
  }

  bool found() const { return found_; }
  double z() const { return zBest_; }
  double s() const { return s_; }
  const D3& normal() const { return normal_; }

 private:
  double halfWidthAt(double s) const { return 0.5 * shape_.widthAt(Float(s)); }

  bool boundMeetsRay(const Quad& q, double s0, double s1) const {
    // Half the width, and half again for the tube parts' ends cut at an angle.
    double r = 1.5 * std::max(halfWidthAt(s0), halfWidthAt(s1));
    double lo[3] = {q[0].x, q[0].y, q[0].z}, hi[3] = {q[0].x, q[0].y, q[0].z};
    for (int i = 1; i < 4; ++i) {
      lo[0] = std::min(lo[0], q[i].x), hi[0] = std::max(hi[0], q[i].x);
      lo[1] = std::min(lo[1], q[i].y), hi[1] = std::max(hi[1], q[i].y);
      lo[2] = std::min(lo[2], q[i].z), hi[2] = std::max(hi[2], q[i].z);
    }
    // Widths vary linearly, so r bounds the whole part; the ray is the positive z axis.
    return lo[0] - r <= 0 && hi[0] + r >= 0 && lo[1] - r <= 0 && hi[1] + r >= 0 && hi[2] + r > 0 &&
           lo[2] - r < zBest_;
  }

  void accept(double z, double s, const D3& n) {
    zBest_ = z;
    s_ = s;
    normal_ = n;
    found_ = true;
  }

  // A direction along the part at one end, in the ray's xy plane; zero when the part has no
  // extent there.
  static void endTangent(const Quad& q, bool atEnd, double* tx, double* ty) {
    for (int k = 1; k <= 3; ++k) {
      D3 d = atEnd ? q[3] - q[3 - k] : q[k] - q[0];
      if (d.x != 0 || d.y != 0) {
        *tx = d.x, *ty = d.y;
        return;
      }
    }
    *tx = *ty = 0;
  }

  void stripLeaf(const Quad& q, double s0, double s1) {
    // The strip ends where lines through the part's ends perpendicular to its tangents cut it,
    // so neighbouring parts neither overlap nor leave a gap (pbrt 3e §3.7.2).
    double tx, ty;
    endTangent(q, false, &tx, &ty);
    if (-(q[0].x * tx + q[0].y * ty) < 0) return;
    endTangent(q, true, &tx, &ty);
    if (-(q[3].x * tx + q[3].y * ty) >= 0) return;
    // The point of the chord closest to the ray, as a fraction of it.
    D3 chord = q[3] - q[0];
    double len2 = chord.x * chord.x + chord.y * chord.y;
    if (len2 == 0) return;
    double w = std::clamp(-(q[0].x * chord.x + q[0].y * chord.y) / len2, 0.0, 1.0);
    double s = s0 + (s1 - s0) * w;
    D3 c = evaluate(q, w);
    double halfWidth = halfWidthAt(s);
    if (shape_.piece().type == CurveType::Ribbon) {
      ribbonHit(c, s, halfWidth);
      return;
    }
    if (c.x * c.x + c.y * c.y >= halfWidth * halfWidth) return;
    if (!(c.z > 0 && c.z < zBest_)) return;
    accept(c.z, s, D3{});
  }

  // A ribbon is a band through the curve point c (ray frame) across its tangent, with the
  // ribbon normal made perpendicular to the tangent as a band's normal must be. pbrt 3e
  // foreshortens the width by the normal and takes c's depth; here the ray meets the band's
  // plane, and the hit counts when its offset from c across the band (along normal x tangent)
  // is within half the width: exact for a straight stretch of band, seen from any side.
  void ribbonHit(const D3& c, double s, double halfWidth) {
    Vector3f tangent;
    evaluate(shape_.piece().bezier, Float(s), &tangent);
    if (tangent.lengthSquared() == 0) return;
    D3 t = toD3(normalize(tangent));
    D3 n = toD3(Vector3f(shape_.ribbonNormal(Float(s))));
    n = n - t * dot(n, t);
    double len = std::sqrt(dot(n, n));
    if (!(len > 0)) return;
    n = n * (1 / len);
    double nz = dot(n, ez_);
    if (nz == 0) return;
    D3 cWorld = ex_ * c.x + ey_ * c.y + ez_ * c.z;  // relative to the ray origin
    double z = dot(cWorld, n) / nz;
    if (!(z > 0 && z < zBest_)) return;
    D3 across{n.y * t.z - n.z * t.y, n.z * t.x - n.x * t.z, n.x * t.y - n.y * t.x};
    if (std::abs(dot(ez_ * z - cWorld, across)) >= halfWidth) return;
    accept(z, s, D3{});
  }

  void roundLeaf(const Quad& q, double s0, double s1) {
    D3 a = q[0], e = q[3] - q[0];
    double ra = halfWidthAt(s0), rb = halfWidthAt(s1), dr = rb - ra;
    // Spheres of radius ra + s dr centred at a + s e: the ray point z (0, 0, z) is inside one
    // when g(z, s) = |z ez - a - s e|^2 - (ra + s dr)^2 <= 0. g is quadratic in s with leading
    // coefficient A; where A > 0 its minimum over s, at s* = (z e.z - B) / A, is zero on the
    // cone tangent to all of them: A g(z, s*) = 0 is a quadratic in z.
    double A = dot(e, e) - dr * dr, B = dot(a, e) - ra * dr;
    if (!(A > 0)) return;  // a part shorter than its change of radius: none at this depth
    // The cone is cut by the planes through the part's ends perpendicular to the curve's
    // tangents there, which neighbouring parts share: no gap opens on the outside of a bend,
    // and the whole curve ends in the open circles Embree's round curves end in.
    D3 t0 = endTangent3(q, false), t1 = endTangent3(q, true);
    double roots[2];
    int n =
        solveQuadratic(A - e.z * e.z, e.z * B - a.z * A, A * (dot(a, a) - ra * ra) - B * B, roots);
    for (int i = 0; i < n; ++i) {
      double z = roots[i];
      if (!(z > 0 && z < zBest_)) continue;
      D3 p{0, 0, z};
      if (dot(p - q[0], t0) < 0 || dot(p - q[3], t1) >= 0) continue;
      double sStar = (z * e.z - B) / A;
      accept(z, s0 + (s1 - s0) * std::clamp(sStar, 0.0, 1.0), p - (a + e * sStar));
      break;
    }
  }

  // The curve's direction at one end of the part (3D); zero when it has no extent.
  static D3 endTangent3(const Quad& q, bool atEnd) {
    for (int k = 1; k <= 3; ++k) {
      D3 d = atEnd ? q[3] - q[3 - k] : q[k] - q[0];
      if (dot(d, d) > 0) return d;
    }
    return D3{};
  }

  const CurveShape& shape_;
  D3 ex_, ey_, ez_;
  double zBest_;
  double s_ = 0;
  D3 normal_;
  bool found_ = false;
};

// Halvings after which every part deviates from its chord by at most eps (cubic_bezier.h).
int depthFor(const CubicBezier& c, double eps) {
  double l0 = maxSecondDifference(c);
  if (!(eps > 0) || l0 <= eps) return 0;
  double d = std::ceil(std::log(0.75 * l0 / eps) / std::log(4.0));
  return int(std::clamp(d, 0.0, 10.0));
}

}  // namespace

bool intersectCurvePiece(const CurveShape& shape, const Ray& ray, CurveHit* hit) {
  const CurvePiece& piece = shape.piece();
  D3 d = toD3(ray.d);
  double len = std::sqrt(dot(d, d));
  if (!(len > 0)) return false;
  D3 ez = d * (1 / len);
  // Any orthonormal pair perpendicular to the ray completes the frame.
  D3 ex = std::abs(ez.x) > std::abs(ez.y) ? D3{-ez.z, 0, ez.x} : D3{0, ez.z, -ez.y};
  ex = ex * (1 / std::sqrt(dot(ex, ex)));
  D3 ey{ez.y * ex.z - ez.z * ex.y, ez.z * ex.x - ez.x * ex.z, ez.x * ex.y - ez.y * ex.x};
  D3 o{ray.o.x, ray.o.y, ray.o.z};
  Quad q;
  for (int i = 0; i < 4; ++i) {
    D3 p = D3{piece.bezier.p[i].x, piece.bezier.p[i].y, piece.bezier.p[i].z} - o;
    q[i] = {dot(p, ex), dot(p, ey), dot(p, ez)};
  }
  // Straight to 1% of the width for strips, whose test is approximate anyway; to 0.01% for
  // tubes, whose parts' surfaces are exact, so that only this chord error remains. Bound
  // culling keeps the cost to about two parts per level along the ray.
  double tolerance = piece.type == CurveType::Cylinder ? 1e-4 : 1e-2;
  double eps = tolerance * std::max(piece.width[0], piece.width[1]);
  if (!(eps > 0)) return false;  // zero width: nothing to hit
  PieceIntersector x(shape, ex, ey, ez, double(ray.tMax) * len);
  x.recurse(q, 0, 1, depthFor(piece.bezier, eps));
  if (!x.found()) return false;
  double t = x.z() / len;
  if (!(Float(t) > 0 && Float(t) < ray.tMax)) return false;
  hit->t = Float(t);
  hit->s = Float(x.s());
  const D3& n = x.normal();
  hit->normal = Vector3f(Float(n.x * ex.x + n.y * ey.x + n.z * ez.x),
                         Float(n.x * ex.y + n.y * ey.y + n.z * ez.y),
                         Float(n.x * ex.z + n.y * ey.z + n.z * ez.z));
  if (hit->normal.lengthSquared() > 0) hit->normal = normalize(hit->normal);
  return true;
}

}  // namespace candela
