// Cubic Bézier curves in 3D (pbrt 3e §3.7): evaluation, de Casteljau splitting, the control
// points of a sub-range by blossoming, and conversion of the other bases pbrt-v3's "curve" shape
// accepts (uniform B-splines, quadratics) to cubic Bézier form.
#pragma once

#include <array>

#include "core/vector.h"

namespace candela {

struct CubicBezier {
  std::array<Point3f, 4> p;
};

// The point at u in [0, 1]; *derivative (when not null) is dp/du there.
Point3f evaluate(const CubicBezier& c, Float u, Vector3f* derivative = nullptr);

// The curve restricted to [u0, u1], reparametrised over [0, 1]: its control points are the
// blossoms p(u0,u0,u0), p(u0,u0,u1), p(u0,u1,u1), p(u1,u1,u1) (pbrt 3e §3.7.1).
CubicBezier subCurve(const CubicBezier& c, Float u0, Float u1);

// The halves [0, 1/2] and [1/2, 1] (de Casteljau).
void splitHalf(const CubicBezier& c, CubicBezier* first, CubicBezier* second);

// Largest |p_i - 2 p_{i+1} + p_{i+2}|: how far the curve is from straight. A curve deviates from
// its chord by at most 3/4 of this (|p''| <= 6 times it, deviation <= |p''|max / 8), and each
// halving divides it by four.
Float maxSecondDifference(const CubicBezier& c);

// Segment of a uniform cubic B-spline with control points q[0..3] (the part between the knots
// of q[1] and q[2]), in Bézier form.
CubicBezier bezierFromCubicBSpline(const Point3f& q0, const Point3f& q1, const Point3f& q2,
                                   const Point3f& q3);
// A quadratic Bézier, degree-elevated to cubic (the same curve and parametrisation).
CubicBezier bezierFromQuadratic(const Point3f& c0, const Point3f& c1, const Point3f& c2);
// Segment of a uniform quadratic B-spline with control points q[0..2], as a cubic Bézier.
CubicBezier bezierFromQuadraticBSpline(const Point3f& q0, const Point3f& q1, const Point3f& q2);

}  // namespace candela
