// The (partial) paraboloid x^2 + y^2 = r^2 z / zMax, zMin <= z <= zMax, 0 <= phi <= phiMax
// (lrt draft §3.5.2): radius r at z = zMax. u = phi / phiMax, v = (z - zMin) / (zMax - zMin); the
// normal points away from the axis (out of the bowl).
#pragma once

#include <memory>

#include "shapes/quadric.h"

namespace candela {

class ParaboloidShape : public Quadric {
 public:
  // zMin and zMax may come in either order; the larger must be positive (checked by the factory;
  // otherwise the shape has no area) and the smaller is clamped to [0, zMax]; phiMaxDeg to
  // [0, 360].
  ParaboloidShape(const Transform& objectToWorld, bool reverseOrientation, Float radius, Float zMin,
                  Float zMax, Float phiMaxDeg);
  Bounds3f objectBound() const override;
  const char* kind() const override { return "paraboloid"; }

 protected:
  void lineCoefficients(const double o[3], const double d[3], double* a, double* b,
                        double* c) const override;
  double implicit(const double p[3], double* fErr, double grad[3]) const override;
  bool clip(double p[3]) const override;
  LocalGeometry geometryAt(const double p[3]) const override;
  // Exact inversion of the height's CDF (the area element is phiMax sqrt(q z + q^2/4) dz).
  void sampleObject(const Point2f& u, double p[3]) const override;

 private:
  // (q z + q^2 / 4)^(3/2): the height's CDF up to a constant.
  double cdf(double z) const;
  double radius_, zMin_, zMax_, phiMax_;
  double q_;  // r^2 / zMax: x^2 + y^2 = q z
};

// "paraboloid": "radius" (1), "zmin" (0), "zmax" (1), "phimax" (360 degrees; "thetamax" in lrt).
std::unique_ptr<Shape> createParaboloidShape(const Transform& objectToWorld,
                                             bool reverseOrientation, const ParamSet& params);

}  // namespace candela
