// pbrt-v2/v3's hyperboloid (pbrt 2e/3e §3.5.3): the surface of revolution x^2 + y^2 = d + k z^2
// fitted to the statement's p1 and p2 as pbrt fits it (see hyperboloid_profile.h), so its
// narrowest section lies at z = 0, between the heights of p1 and p2 and within 0 <= phi <= phiMax.
//
// The parameterisation is pbrt's: v = (z - z1) / (z2 - z1), and phi = u phiMax is the angle from
// the segment's point at that height, p1 + v (p2 - p1), to the surface point. Where the segment is
// a ruling of the fitted surface (its own narrowest point at z = 0) this is the lrt draft's sweep
// of the segment (§3.5.3); otherwise p1 is not on the surface and the draft's sweep is a
// different shape (a wide bowl where pbrt draws a narrow tower): pbrt-v2 and v3 agree on the fit,
// so it is followed.
//
// Unlike pbrt-v3: dp/dv is the derivative of this parameterisation on the fitted surface (pbrt
// uses the segment's direction turned by phi, tangent only on a ruling; HyperboloidNormal chooses),
// so the normal is the surface's; the bounds cover the fitted surface (pbrt bounds by p1's and p2's
// radii, which can cut the surface off); the area is exact and area sampling works (pbrt-v3 has
// neither). The normal points away from the axis whichever end is higher.
#pragma once

#include <memory>

#include "core/compatibility.h"
#include "shapes/hyperboloid_profile.h"
#include "shapes/quadric.h"

namespace candela {

class HyperboloidShape : public Quadric {
 public:
  // p1 and p2 must differ in z (checked by the factory; otherwise the shape has no area);
  // phiMaxDeg is clamped to [0, 360].
  HyperboloidShape(const Transform& objectToWorld, bool reverseOrientation, const Point3f& p1,
                   const Point3f& p2, Float phiMaxDeg,
                   HyperboloidNormal normal = HyperboloidNormal::Exact);
  Bounds3f objectBound() const override;
  const char* kind() const override { return "hyperboloid"; }
  // The fitted surface rho^2 = d + k z^2.
  const HyperboloidFit& fit() const { return fit_; }

 protected:
  void lineCoefficients(const double o[3], const double d[3], double* a, double* b,
                        double* c) const override;
  double implicit(const double p[3], double* fErr, double grad[3]) const override;
  bool clip(double p[3]) const override;
  LocalGeometry geometryAt(const double p[3]) const override;
  // z by inverting the profile's area function; phi uniform.
  void sampleObject(const Point2f& u, double p[3]) const override;

 private:
  // The segment's point at parameter v, projected on the xy plane.
  void segmentPoint(double v, double* x, double* y) const;
  // The angle from the segment's point at v to p about the axis, in [0, 2 pi).
  double sweepAngle(const double p[3], double v) const;
  HyperboloidFit fit_;
  HyperboloidProfile profile_;
  double delta_[3], invDz_;
  // The segment's squared distance from the axis R(v) = alpha v^2 + beta v + gamma, and
  // x1 dy - y1 dx: its angle turns at the rate cross_ / R(v).
  double alpha_, beta_, gamma_, cross_;
  double rMax_, zMin_, zMax_, phiMax_;
  HyperboloidNormal normal_;
};

// "hyperboloid": "p1" (0 0 0), "p2" (1 1 1), "phimax" (360 degrees; "thetamax" in lrt).
std::unique_ptr<Shape> createHyperboloidShape(const Transform& objectToWorld,
                                              bool reverseOrientation, const ParamSet& params,
                                              HyperboloidNormal normal = HyperboloidNormal::Exact);

}  // namespace candela
