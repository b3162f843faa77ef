// The (partial) cylinder x^2 + y^2 = r^2, zMin <= z <= zMax, 0 <= phi <= phiMax (lrt draft
// §3.3). u = phi / phiMax, v = (z - zMin) / (zMax - zMin); the normal points away from the axis.
#pragma once

#include <memory>

#include "shapes/quadric.h"

namespace candela {

class CylinderShape : public Quadric {
 public:
  // zMin and zMax may come in either order; phiMaxDeg is clamped to [0, 360].
  CylinderShape(const Transform& objectToWorld, bool reverseOrientation, Float radius, Float zMin,
                Float zMax, Float phiMaxDeg);
  Bounds3f objectBound() const override;
  const char* kind() const override { return "cylinder"; }

 protected:
  void lineCoefficients(const double o[3], const double d[3], double* a, double* b,
                        double* c) const override;
  double implicit(const double p[3], double* fErr, double grad[3]) const override;
  bool clip(double p[3]) const override;
  LocalGeometry geometryAt(const double p[3]) const override;
  void sampleObject(const Point2f& u, double p[3]) const override;

 private:
  double radius_, zMin_, zMax_, phiMax_;
};

// "cylinder": "radius" (1), "zmin" (-1), "zmax" (1), "phimax" (360 degrees; "thetamax" in lrt).
std::unique_ptr<Shape> createCylinderShape(const Transform& objectToWorld, bool reverseOrientation,
                                           const ParamSet& params);

}  // namespace candela
