#include "shapes/cubic_bezier.h"

#include <algorithm>

namespace candela {

namespace {

Point3f mix(Float t, const Point3f& a, const Point3f& b) { return lerp(t, a, b); }

// The blossom p(a, b, c): de Casteljau with a different parameter at each level.
Point3f blossom(const CubicBezier& c, Float a, Float b, Float t) {
  Point3f l1[3] = {mix(a, c.p[0], c.p[1]), mix(a, c.p[1], c.p[2]), mix(a, c.p[2], c.p[3])};
  Point3f l2[2] = {mix(b, l1[0], l1[1]), mix(b, l1[1], l1[2])};
  return mix(t, l2[0], l2[1]);
}

}  // namespace

Point3f evaluate(const CubicBezier& c, Float u, Vector3f* derivative) {
  Point3f l1[3] = {mix(u, c.p[0], c.p[1]), mix(u, c.p[1], c.p[2]), mix(u, c.p[2], c.p[3])};
  Point3f l2[2] = {mix(u, l1[0], l1[1]), mix(u, l1[1], l1[2])};
  if (derivative) {
    // The last level's two points span the tangent: p'(u) = 3 (l2[1] - l2[0]). When they
    // coincide (a repeated end control point), the second level's end difference stands in.
    Vector3f d = l2[1] - l2[0];
    if (d.lengthSquared() == 0) d = u < Float(0.5) ? c.p[2] - c.p[0] : c.p[3] - c.p[1];
    *derivative = d * 3;
  }
  return mix(u, l2[0], l2[1]);
}

CubicBezier subCurve(const CubicBezier& c, Float u0, Float u1) {
  return {{blossom(c, u0, u0, u0), blossom(c, u0, u0, u1), blossom(c, u0, u1, u1),
           blossom(c, u1, u1, u1)}};
}

void splitHalf(const CubicBezier& c, CubicBezier* first, CubicBezier* second) {
  Point3f a = mix(0.5f, c.p[0], c.p[1]), b = mix(0.5f, c.p[1], c.p[2]),
          d = mix(0.5f, c.p[2], c.p[3]);
  Point3f ab = mix(0.5f, a, b), bd = mix(0.5f, b, d);
  Point3f mid = mix(0.5f, ab, bd);
  *first = {{c.p[0], a, ab, mid}};
  *second = {{mid, bd, d, c.p[3]}};
}

Float maxSecondDifference(const CubicBezier& c) {
  Float m = 0;
  for (int i = 0; i < 2; ++i) {
    Vector3f d = (c.p[i] - c.p[i + 1]) + (c.p[i + 2] - c.p[i + 1]);
    m = std::max(m, d.length());
  }
  return m;
}

CubicBezier bezierFromCubicBSpline(const Point3f& q0, const Point3f& q1, const Point3f& q2,
                                   const Point3f& q3) {
  // The uniform B-spline basis matrix rewritten in the Bernstein basis: the segment's ends are
  // (q0 + 4 q1 + q2) / 6 and (q1 + 4 q2 + q3) / 6; its inner Bézier points trisect q1 q2.
  Point3f b1 = mix(Float(1) / 3, q1, q2), b2 = mix(Float(2) / 3, q1, q2);
  // The ends are the midpoints between these and the neighbouring segments' inner points.
  Point3f b0 = mix(0.5f, mix(Float(2) / 3, q0, q1), b1);
  Point3f b3 = mix(0.5f, b2, mix(Float(1) / 3, q2, q3));
  return {{b0, b1, b2, b3}};
}

CubicBezier bezierFromQuadratic(const Point3f& c0, const Point3f& c1, const Point3f& c2) {
  return {{c0, mix(Float(2) / 3, c0, c1), mix(Float(1) / 3, c1, c2), c2}};
}

CubicBezier bezierFromQuadraticBSpline(const Point3f& q0, const Point3f& q1, const Point3f& q2) {
  // A uniform quadratic B-spline segment runs from the midpoint of q0 q1 to that of q1 q2 with
  // q1 as its Bézier middle point.
  return bezierFromQuadratic(mix(0.5f, q0, q1), q1, mix(0.5f, q1, q2));
}

}  // namespace candela
