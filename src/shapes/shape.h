// The geometric shape interface (lrt draft §3.1, sampling §15.6). Intersection is in world space;
// shapes keep whatever transform they need. Embree drives the intersection search; a shape
// answers for one primitive (a quadric, or one triangle of a mesh).
#pragma once

#include "core/bounds.h"
#include "core/direction_cone.h"
#include "core/interaction.h"

namespace candela {

struct TriangleMesh;

class Shape {
 public:
  virtual ~Shape() = default;
  virtual Bounds3f worldBound() const = 0;
  // Closest hit with t in (0, ray.tMax); fills *tHit and, when isect is not null, *isect.
  virtual bool intersect(const Ray& ray, Float* tHit, SurfaceInteraction* isect) const = 0;
  virtual bool intersectP(const Ray& ray) const {
    Float t;
    return intersect(ray, &t, nullptr);
  }
  virtual Float area() const = 0;
  // A point uniformly distributed by area; *pdf is with respect to area.
  virtual Interaction sample(const Point2f& u, Float* pdf) const = 0;
  // A point as seen from ref; *pdf is with respect to solid angle at ref. The default converts the
  // area sample; shapes that can do better (the sphere's cone) override.
  virtual Interaction sample(const Interaction& ref, const Point2f& u, Float* pdf) const;
  // sample(ref, u, pdf) and the unit direction wi from ref to the point (set when *pdf is not 0),
  // which a light needs and a shape that converts the density has already found. The default
  // normalises the point's offset from ref.
  virtual Interaction sampleFrom(const Interaction& ref, const Point2f& u, Float* pdf,
                                 Vector3f* wi) const;
  // Solid-angle density at ref of sample(ref, ...) producing direction wi.
  virtual Float pdf(const Interaction& ref, const Vector3f& wi) const;
  // The triangle mesh and triangle index when this shape is a triangle of a mesh, which the
  // Embree aggregate hands to Embree as native triangles; nullptr otherwise.
  virtual const TriangleMesh* triangleMesh(int* /*triangleIndex*/) const { return nullptr; }
  // A cone holding the normals of every interaction on the shape, as oriented there (the side a
  // one-sided area light emits from): what the light tree bounds a light's emission by. The
  // default, every direction, is true of any shape.
  virtual DirectionCone normalBound() const { return DirectionCone::everyDirection(); }
  // A short name for statistics ("sphere", "triangle").
  virtual const char* kind() const = 0;
};

}  // namespace candela
