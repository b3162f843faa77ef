// The (partial) annulus at z = height: innerRadius <= sqrt(x^2 + y^2) <= radius,
// 0 <= phi <= phiMax (lrt draft §3.4, with pbrt-v2's inner radius). u = phi / phiMax,
// v = (radius - rho) / (radius - innerRadius); the normal is +z.
#pragma once

#include <memory>

#include "shapes/quadric.h"

namespace candela {

class DiskShape : public Quadric {
 public:
  // innerRadius is clamped to [0, radius]; phiMaxDeg to [0, 360].
  DiskShape(const Transform& objectToWorld, bool reverseOrientation, Float height, Float radius,
            Float innerRadius, Float phiMaxDeg);
  Bounds3f objectBound() const override;
  // Exact for every affine transform: a plane's areas all scale by the same factor.
  Float area() const override;
  const char* kind() const override { return "disk"; }

 protected:
  void lineCoefficients(const double o[3], const double d[3], double* a, double* b,
                        double* c) const override;
  double implicit(const double p[3], double* fErr, double grad[3]) const override;
  bool clip(double p[3]) const override;
  LocalGeometry geometryAt(const double p[3]) const override;
  // The whole disk by Shirley and Chiu's concentric map (lrt draft §14.5.2), which keeps the
  // samples' stratification; annuli and partial sweeps by inverting the radius and angle CDFs. No
  // rejection loop, unlike the draft's RejectionSampleDisk (seed notes §24).
  void sampleObject(const Point2f& u, double p[3]) const override;

 private:
  double height_, radius_, innerRadius_, phiMax_;
  double worldAreaScale_;  // |M x-axis x M y-axis|: world area per object area in the plane
};

// "disk": "height" (0), "radius" (1), "innerradius" (0), "phimax" (360 degrees; "thetamax" in lrt).
std::unique_ptr<Shape> createDiskShape(const Transform& objectToWorld, bool reverseOrientation,
                                       const ParamSet& params);

}  // namespace candela
