// Cubic Bézier pieces of the "curve" shape: a sub-range's control points and the two halves
// trace the same points as the whole curve, and the derivative is the curve's.
#include <gtest/gtest.h>

#include "shapes/cubic_bezier.h"

namespace candela {
namespace {

const CubicBezier kCurve{
    {Point3f(0, 0, 0), Point3f(1, 2, -1), Point3f(2, -1, 3), Point3f(4, 1, 0)}};

void expectNear(const Point3f& a, const Point3f& b, Float tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

TEST(CubicBezier, SubCurveTracesTheSameRange) {
  const Float u0 = 0.2f, u1 = 0.7f;
  CubicBezier sub = subCurve(kCurve, u0, u1);
  for (int i = 0; i <= 10; ++i) {
    Float s = Float(i) / 10;
    expectNear(evaluate(sub, s), evaluate(kCurve, lerp(s, u0, u1)), 1e-5f);
  }
}

TEST(CubicBezier, HalvesTraceTheTwoHalves) {
  CubicBezier a, b;
  splitHalf(kCurve, &a, &b);
  for (int i = 0; i <= 10; ++i) {
    Float s = Float(i) / 10;
    expectNear(evaluate(a, s), evaluate(kCurve, s / 2), 1e-5f);
    expectNear(evaluate(b, s), evaluate(kCurve, 0.5f + s / 2), 1e-5f);
  }
}

TEST(CubicBezier, DerivativeIsTheCurvesSlope) {
  // Central differences with h = 1e-3: truncation h^2 |p'''| / 6 < 2e-5 here, float rounding of
  // the points (magnitude < 5) over 2h about 3e-4.
  for (int i = 1; i <= 9; ++i) {
    Float u = Float(i) / 10, h = 1e-3f;
    Vector3f d;
    evaluate(kCurve, u, &d);
    Vector3f fd = (evaluate(kCurve, u + h) - evaluate(kCurve, u - h)) / (2 * h);
    EXPECT_NEAR(d.x, fd.x, 1e-3f);
    EXPECT_NEAR(d.y, fd.y, 1e-3f);
    EXPECT_NEAR(d.z, fd.z, 1e-3f);
  }
}

TEST(CubicBezier, BSplineAndQuadraticFormsMatchTheirBases) {
  // Uniform B-spline segments, evaluated from their basis functions.
  Point3f q[4] = {Point3f(0, 0, 0), Point3f(1, 2, 0), Point3f(3, -1, 1), Point3f(4, 1, 2)};
  CubicBezier cubic = bezierFromCubicBSpline(q[0], q[1], q[2], q[3]);
  CubicBezier quadratic = bezierFromQuadraticBSpline(q[0], q[1], q[2]);
  for (int i = 0; i <= 10; ++i) {
    Float t = Float(i) / 10, s = 1 - t;
    Float b[4] = {s * s * s / 6, (3 * t * t * t - 6 * t * t + 4) / 6,
                  (-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6, t * t * t / 6};
    Point3f expected = q[0] * b[0] + q[1] * b[1] + q[2] * b[2] + q[3] * b[3];
    expectNear(evaluate(cubic, t), expected, 1e-5f);
    Float c[3] = {s * s / 2, (-2 * t * t + 2 * t + 1) / 2, t * t / 2};
    expectNear(evaluate(quadratic, t), q[0] * c[0] + q[1] * c[1] + q[2] * c[2], 1e-5f);
  }
}

}  // namespace
}  // namespace candela
