// The (partial) cone with its base circle of the given radius at z = 0 and apex at z = height,
// 0 <= phi <= phiMax (lrt draft §3.5.1): x = r (1 - v) cos phi, y = r (1 - v) sin phi, z = v h,
// u = phi / phiMax. The normal points away from the axis.
#pragma once

#include <memory>

#include "shapes/quadric.h"

namespace candela {

class ConeShape : public Quadric {
 public:
  // height may be negative (the apex below the base); phiMaxDeg is clamped to [0, 360].
  ConeShape(const Transform& objectToWorld, bool reverseOrientation, Float height, Float radius,
            Float phiMaxDeg);
  Bounds3f objectBound() const override;
  const char* kind() const override { return "cone"; }

 protected:
  void lineCoefficients(const double o[3], const double d[3], double* a, double* b,
                        double* c) const override;
  double implicit(const double p[3], double* fErr, double grad[3]) const override;
  bool clip(double p[3]) const override;
  LocalGeometry geometryAt(const double p[3]) const override;
  void sampleObject(const Point2f& u, double p[3]) const override;

 private:
  double height_, radius_, phiMax_;
  double k_;  // (r / h)^2
};

// "cone": "radius" (1), "height" (1), "phimax" (360 degrees; "thetamax" in lrt).
std::unique_ptr<Shape> createConeShape(const Transform& objectToWorld, bool reverseOrientation,
                                       const ParamSet& params);

}  // namespace candela
