// The (partial) surface swept by the segment p1 p2 turning about the z axis through
// 0 <= phi <= phiMax (lrt draft §3.5.3): a hyperboloid of one sheet, or a cone or cylinder when
// the segment meets or parallels the axis. p = Rz(phi) (p1 + v (p2 - p1)), u = phi / phiMax. The
// normal points away from the axis whichever end is higher.
//
// Unlike pbrt-v2, which fits x^2/a + y^2/a - z^2/c = 1 and so assumes the waist at z = 0, the
// implicit form here is exact for any segment: x^2 + y^2 = R(v(z)), where R(v) is the squared
// distance from the axis of p1 + v (p2 - p1) and v(z) = (z - z1) / (z2 - z1).
#pragma once

#include <memory>

#include "shapes/quadric.h"

namespace candela {

class HyperboloidShape : public Quadric {
 public:
  // p1 and p2 must differ in z (checked by the factory; otherwise the shape has no area);
  // phiMaxDeg is clamped to [0, 360].
  HyperboloidShape(const Transform& objectToWorld, bool reverseOrientation, const Point3f& p1,
                   const Point3f& p2, Float phiMaxDeg);
  Bounds3f objectBound() const override;
  const char* kind() const override { return "hyperboloid"; }

 protected:
  void lineCoefficients(const double o[3], const double d[3], double* a, double* b,
                        double* c) const override;
  double implicit(const double p[3], double* fErr, double grad[3]) const override;
  bool clip(double p[3]) const override;
  LocalGeometry geometryAt(const double p[3]) const override;
  // v by inverting the closed-form arc-area function with safeguarded Newton steps (a fixed
  // maximum number, no open loop); phi uniform.
  void sampleObject(const Point2f& u, double p[3]) const override;

 private:
  // The rotation angle taking the segment's point at height z to p, in [0, 2 pi).
  double sweepAngle(const double p[3], double v) const;
  // Area of the strip 0..v of the full (2 pi) sweep divided by 2 pi: the integral of
  // sqrt(Q(v)) = |dp/du x dp/dv| / phiMax.
  double stripIntegral(double v) const;
  double p1_[3], delta_[3];
  double invDz_;
  double alpha_, beta_, gamma_;  // R(v) = alpha v^2 + beta v + gamma
  double qa_, qb_, qd_;          // Q(v) = qa (v + qb)^2 + qd
  double rMax_, zMin_, zMax_, phiMax_;
};

// "hyperboloid": "p1" (0 0 0), "p2" (1 1 1), "phimax" (360 degrees; "thetamax" in lrt).
std::unique_ptr<Shape> createHyperboloidShape(const Transform& objectToWorld,
                                              bool reverseOrientation, const ParamSet& params);

}  // namespace candela
