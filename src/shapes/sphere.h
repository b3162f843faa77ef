// The (partial) sphere quadric (lrt draft §3.2; sampling §15.6; error bounds pbrt 3e §3.9).
// Intersection runs in object space, reached from world space in double precision through the
// inverse (computed in double) of the float objectToWorld matrix, so the two transforms agree to
// double precision and add almost no error: a sphere far from the origin is hit as precisely as
// one at it. The hit is reprojected onto the sphere, mapped back in double, and carries a
// conservative bound on its position error so that spawned rays never re-hit it. The transform
// must be affine (its last row 0 0 0 1), as every shape transform is.
#pragma once

#include <memory>

#include "core/paramset.h"
#include "core/transform.h"
#include "shapes/shape.h"

namespace candela {

class SphereShape : public Shape {
 public:
  // zMin/zMax are clamped to [-radius, radius]; phiMaxDeg to [0, 360] (the draft's "thetamax").
  SphereShape(const Transform& objectToWorld, bool reverseOrientation, Float radius, Float zMin,
              Float zMax, Float phiMaxDeg);

  Bounds3f objectBound() const;
  Bounds3f worldBound() const override;
  bool intersect(const Ray& ray, Float* tHit, SurfaceInteraction* isect) const override;
  bool intersectP(const Ray& ray) const override;
  // World-space area. Exact when objectToWorld is a similarity (rotation, translation, uniform
  // scale); for other transforms the uniform scale of equal volume is used (an approximation).
  Float area() const override;
  // Uniform by area over the (partial) sphere: z uniform in [zMin, zMax] and phi in [0, phiMax]
  // is uniform by area (Archimedes), so partial spheres are sampled exactly, unlike the draft.
  Interaction sample(const Point2f& u, Float* pdf) const override;
  // Full spheres under a similarity transform, seen from outside: uniform over the cone the
  // sphere subtends (pbrt 3e §14.2.2). Otherwise (inside, partial sphere, non-uniform scale) the
  // area sample converted to solid angle.
  Interaction sample(const Interaction& ref, const Point2f& u, Float* pdf) const override;
  Float pdf(const Interaction& ref, const Vector3f& wi) const override;
  const char* kind() const override { return "sphere"; }

  Float radius() const { return radius_; }
  const Transform& objectToWorld() const { return objectToWorld_; }
  const Transform& worldToObject() const { return worldToObject_; }

 private:
  // Shared by intersect and intersectP: the object-space hit, or false.
  struct Hit {
    Float t;      // ray parameter (the same in both spaces: the maps are affine)
    double p[3];  // object space, reprojected onto the sphere, pole-nudged
    Float phi;
  };
  bool findHit(const Ray& ray, Hit* hit) const;
  // An object-space point on the sphere in world space, with its error bound.
  Point3f toWorld(const double p[3], Vector3f* pError) const;
  bool usesConeSampling() const { return isFullSphere_ && isSimilarity_; }
  // True when the origin offset from ref toward the centre lies inside the sphere.
  bool refInside(const Interaction& ref) const;

  Transform objectToWorld_, worldToObject_;
  double o2w_[3][4], w2o_[3][4];  // the affine rows, w2o_ the inverse of o2w_ in double
  bool invertible_;
  bool reverseOrientation_, transformSwapsHandedness_;
  Float radius_, zMin_, zMax_, thetaZMin_, thetaZMax_, phiMax_;
  bool isFullSphere_;
  bool isSimilarity_;  // objectToWorld keeps spheres spheres
  Float worldScale_;   // world length per object length (exact for similarities)
  Point3f worldCenter_;
  Float worldRadius_;
};

// The "sphere" shape: "radius" (1), "zmin" (-radius), "zmax" (radius), "phimax" (360 degrees).
std::unique_ptr<Shape> createSphereShape(const Transform& objectToWorld, bool reverseOrientation,
                                         const ParamSet& params);

}  // namespace candela
