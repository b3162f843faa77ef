// What the quadrics share (lrt draft §3.2–3.5): the world/object maps in double precision, the
// ray-quadric root search with its floating-point guard, the hit point's error bound, the
// Weingarten equations, world bounds, area and area sampling. Each quadric (sphere, cylinder,
// disk, cone, paraboloid, hyperboloid) supplies its implicit function, parameterisation and
// ranges.
//
// Robustness (pbrt 3e §3.9, in double where pbrt uses EFloat): the ray goes to object space in
// double through the inverse of the float objectToWorld matrix computed in double, so a quadric
// far from the origin or at any scale is hit as precisely as a unit one at the origin. Roots
// closer to the ray origin than their own uncertainty are rejected (the surface a spawned ray
// leaves), and the hit's world error bound covers both the transform and the hit's distance from
// the exact surface, measured by the implicit function's residual.
#pragma once

#include <numbers>

#include "core/paramset.h"
#include "core/transform.h"
#include "shapes/shape.h"

namespace candela {

class Quadric : public Shape {
 public:
  Bounds3f worldBound() const override;
  bool intersect(const Ray& ray, Float* tHit, SurfaceInteraction* isect) const override;
  bool intersectP(const Ray& ray) const override;
  // World-space area: the object-space area times the area scale of objectToWorld. Exact for
  // similarity transforms (rotation, translation, uniform scale); otherwise the uniform scale of
  // equal volume is used, an approximation. DiskShape overrides it with the exact value.
  Float area() const override;
  // Uniform by object-space area, hence by world area under a similarity transform; *pdf = 1/area.
  Interaction sample(const Point2f& u, Float* pdf) const override;
  using Shape::sample;  // the solid-angle version: the area sample converted

  virtual Bounds3f objectBound() const = 0;
  const Transform& objectToWorld() const { return objectToWorld_; }

 protected:
  // objectToWorld must be affine (its last row 0 0 0 1), as every shape transform is.
  Quadric(const Transform& objectToWorld, bool reverseOrientation);

  // The implicit function F (F = 0 on the surface, its gradient pointing outward: away from the
  // axis, or +z for the disk), restricted to the line o + t d: F = a t^2 + b t + c.
  virtual void lineCoefficients(const double o[3], const double d[3], double* a, double* b,
                                double* c) const = 0;
  // F(p), with a bound on the rounding error of that evaluation in *fErr, and grad F(p).
  virtual double implicit(const double p[3], double* fErr, double grad[3]) const = 0;
  // Whether a point of the (unbounded) quadric lies on this shape: its z or radius range and
  // sweep angle. May first move p onto the surface where that is exact and cheap.
  virtual bool clip(double p[3]) const = 0;
  // The parameterisation at p (lrt draft §3.2.3): (u, v), first and second derivatives. Singular
  // points (poles, apex, disk centre) must return finite, non-parallel tangents.
  struct LocalGeometry {
    Point2f uv;
    Vector3f dpdu, dpdv, d2Pduu, d2Pduv, d2Pdvv;
  };
  virtual LocalGeometry geometryAt(const double p[3]) const = 0;
  // A point uniformly distributed by object-space area, on the surface to double precision.
  virtual void sampleObject(const Point2f& u, double p[3]) const = 0;

  // Object-space area, set by the derived constructor (exact, in closed form).
  double objectArea_ = 0;
  // A ball that holds the shape, for a cheap rejection of the rays that pass it by (most rays
  // a user-geometry callback is asked about): call one of these at the end of a derived
  // constructor. The ball about objectBound(), or a tighter one (object space).
  void setBoundingBall();
  void setBoundingBall(const double centre[3], double radius);
  // The shape's parameterisation has cross(dp/du, dp/dv) pointing inward (a hyperboloid whose p2
  // is below p1, a cone of negative height): normals are turned outward. Set by the derived
  // constructor.
  bool crossPointsInward_ = false;

  // The azimuth of (x, y) in [0, 2 pi).
  static double azimuth(double x, double y);
  // Sweep-angle limit in radians (phiMaxDeg clamped to [0, 360]).
  static double phiMaxRadians(Float phiMaxDeg);
  // The smallest distance from the axis at which tangents are evaluated: a hit closer to the
  // axis (a pole or apex, where phi is undefined and dp/du vanishes) is evaluated this far out,
  // 1e-5 of the shape's radius: pbrt 3e's pole nudge for the sphere (§3.2.2), for every axis.
  static constexpr double kAxisNudge = 1e-5;

  // An object-space point near the surface in world space, with its error bound: the transform's
  // rounding plus the point's distance from the exact surface (from F's residual).
  Point3f toWorld(const double p[3], Vector3f* pError) const;
  // A world-space vector in object space, in double (the inverse's linear part).
  void toObjectVector(const Vector3f& w, double v[3]) const;
  // Whether objectToWorld keeps spheres spheres (a similarity), and its scale: world length per
  // object length, exact for similarities (otherwise that of equal volume).
  bool isSimilarity() const { return isSimilarity_; }
  bool reverseOrientation() const { return reverseOrientation_; }
  double worldScale() const { return worldScale_; }

 private:
  struct Hit {
    Float t;
    double p[3];  // object space
  };
  bool findHit(const Ray& ray, Hit* hit) const;
  // Whether the ray certainly has no point of the bounding ball for t in [0, tMax].
  bool passesBall(const Ray& ray) const;
  // The outward object-space normal's derivatives (Weingarten equations, lrt draft §3.2.4).
  static void weingarten(const LocalGeometry& g, Normal3f* dndu, Normal3f* dndv);
  double objectExtent() const;

  Transform objectToWorld_;
  double o2w_[3][4], w2o_[3][4];  // the affine rows; w2o_ is o2w_'s inverse, computed in double
  // The bounding ball in world space (setBoundingBall); none: nothing is rejected by it.
  Point3f worldBallCentre_;
  Float worldBallRadius_ = 0;
  bool hasWorldBall_ = false;
  bool invertible_;
  bool reverseOrientation_, transformSwapsHandedness_;
  bool isSimilarity_;
  double worldScale_;
};

// The sweep angle of a quadric's parameters: pbrt's "phimax", or the lrt draft's name for the same
// angle, "thetamax" (lrt draft App. C), in degrees; def when neither is given.
Float quadricPhiMax(const ParamSet& params, Float def = 360);

}  // namespace candela
