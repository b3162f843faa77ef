// The (partial) sphere x^2 + y^2 + z^2 = r^2, zMin <= z <= zMax, 0 <= phi <= phiMax (lrt draft
// §3.2). u = phi / phiMax, v = (theta - thetaZMin) / (thetaZMax - thetaZMin), theta the polar
// angle; the normal points outward. Intersection, error bounds and area sampling are Quadric's;
// the sphere adds sampling of the cone it subtends (lrt draft §15.6.3).
#pragma once

#include <memory>

#include "shapes/quadric.h"

namespace candela {

class SphereShape : public Quadric {
 public:
  // zMin/zMax come in either order and are clamped to [-radius, radius]; phiMaxDeg to [0, 360]
  // (the draft's "thetamax").
  SphereShape(const Transform& objectToWorld, bool reverseOrientation, Float radius, Float zMin,
              Float zMax, Float phiMaxDeg);

  Bounds3f objectBound() const override;
  // Uniform by area (Quadric's): z uniform in [zMin, zMax] and phi in [0, phiMax] is uniform by
  // area (Archimedes), so partial spheres are sampled exactly, unlike the draft.
  using Quadric::sample;
  // Full spheres under a similarity transform, seen from outside: uniform over the cone the
  // sphere subtends (pbrt 3e §14.2.2). Otherwise (inside, partial sphere, non-uniform scale) the
  // area sample converted to solid angle.
  Interaction sample(const Interaction& ref, const Point2f& u, Float* pdf) const override;
  Float pdf(const Interaction& ref, const Vector3f& wi) const override;
  const char* kind() const override { return "sphere"; }

  Float radius() const { return Float(radius_); }
  // A whole sphere under a similarity transform is the surface of a ball in world space: its
  // centre and radius then, false otherwise (a benchmark gives such spheres to Embree natively).
  bool worldBall(Point3f* centre, Float* radius) const {
    if (!usesConeSampling()) return false;
    *centre = worldCenter_;
    *radius = worldRadius_;
    return true;
  }

 protected:
  void lineCoefficients(const double o[3], const double d[3], double* a, double* b,
                        double* c) const override;
  double implicit(const double p[3], double* fErr, double grad[3]) const override;
  bool clip(double p[3]) const override;
  LocalGeometry geometryAt(const double p[3]) const override;
  void sampleObject(const Point2f& u, double p[3]) const override;

 private:
  bool usesConeSampling() const { return isFullSphere_ && isSimilarity(); }
  // True when the origin offset from ref toward the centre lies inside the sphere.
  bool refInside(const Interaction& ref) const;

  double radius_, zMin_, zMax_, thetaZMin_, thetaZMax_, phiMax_;
  bool isFullSphere_;
  Point3f worldCenter_;
  Float worldRadius_;
};

// The "sphere" shape: "radius" (1), "zmin" (-radius), "zmax" (radius), "phimax" (360 degrees).
std::unique_ptr<Shape> createSphereShape(const Transform& objectToWorld, bool reverseOrientation,
                                         const ParamSet& params);

}  // namespace candela
