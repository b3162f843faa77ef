// The Aggregate on Embree (DESIGN.md, "Intersection is Embree's"). Runs of consecutive triangles
// of one mesh become one native Embree triangle geometry, runs of curve pieces of one type one
// native Embree curve geometry; every other shape (the quadrics) is a primitive of one Embree
// user geometry whose callbacks call the shape's own intersection.
// Object instances (ObjectBegin/ObjectInstance, lrt draft §4.1.2) share one child scene per
// prototype: a static instance is an Embree instance geometry of it, so memory does not grow
// with the number of instances; instances with animated transforms are primitives of a user
// geometry that queries the child scene with the ray taken to prototype space at its time
// (Embree would interpolate the matrices entry by entry; the book decomposes them, pbrt 2e
// §2.9.3). Debian's Embree has one instancing level, which is all pbrt scenes can express.
#pragma once

#include <memory>
#include <vector>

#include "accel/aggregate.h"
#include "accel/embree/embree_device.h"
#include "accel/scene_geometry.h"

struct RTCSceneTy;     // Embree's RTCScene is RTCSceneTy*
struct RTCGeometryTy;  // and RTCGeometry is RTCGeometryTy*

namespace candela {

struct EmbreeGeometry;
struct QueryContext;

// A closest hit as Embree reports it, for one ray of a single query or a packet.
struct EmbreeHit {
  unsigned geomID, primID, instID;
  float u, v;
  Vector3f ng;  // the geometric normal
  float t;
};

class EmbreeAggregate : public Aggregate {
 public:
  enum class BuildQuality { Medium, High };

  // Neither device nor primitives is copied: both must outlive the aggregate, and primitives
  // must stay where they are, since hits point into them. Throws EmbreeError when Embree fails.
  EmbreeAggregate(const EmbreeDevice& device, const std::vector<Primitive>& primitives,
                  BuildQuality quality = BuildQuality::Medium);
  // All of geometry: its world-space primitives, and its instances, each prototype built once
  // (only if some instance uses it and it has primitives). geometry is not copied and must
  // outlive the aggregate unchanged. A hit inside an instance reports the prototype's
  // primitive and the interaction in world space.
  EmbreeAggregate(const EmbreeDevice& device, const SceneGeometry& geometry,
                  BuildQuality quality = BuildQuality::Medium);
  ~EmbreeAggregate() override;
  EmbreeAggregate(const EmbreeAggregate&) = delete;
  EmbreeAggregate& operator=(const EmbreeAggregate&) = delete;

  Bounds3f worldBound() const override { return bounds_; }
  // Rays with NaN or infinite origin or direction components, a zero direction or a NaN tMax
  // miss. Hits at t = 0 are excluded (Embree's own test accepts t == tnear).
  bool intersect(const Ray& ray, SurfaceInteraction* isect) const override;
  bool intersectP(const Ray& ray) const override;
  // As Embree packets of eight (RTC_INTERSECT_CONTEXT_FLAG_COHERENT) when no geometry has
  // callbacks that take one ray at a time (user geometries); otherwise one ray at a time.
  void intersectCoherent(std::span<const Ray> rays, SurfaceInteraction* isects,
                         bool* hits) const override;
  bool tracesCoherentRaysFaster() const override { return packetQueries_; }
  // counts: "embree triangle geometries", "embree user geometries", "triangles",
  // "user primitives", and with curves "embree curve geometries", "curves" (of this scene,
  // prototypes not included); with instances also "instances", "prototypes", "embree instance
  // geometries" (static instances), "embree motion user geometries", "motion instances", "prototype
  // triangles", "prototype user primitives".
  AggregateStats stats() const override;

 private:
  EmbreeAggregate(const EmbreeDevice& device, const Primitive* primitives, size_t count,
                  const SceneGeometry* geometry, BuildQuality quality);
  void addPrimitives(const Primitive* primitives, size_t count);
  void addInstances(const SceneGeometry& geometry);
  unsigned attach(RTCGeometryTy* g, std::unique_ptr<EmbreeGeometry> info);
  // The interaction of a hit that Embree reported for ray; false when the hit is refused (as
  // interactionAt may). Sets ray.tMax to the hit's distance. Always inlined: intersect's own
  // work after Embree's (GCC would call it, at about 1 % of a render's instructions).
  [[gnu::always_inline]] inline bool finishHit(const Ray& ray, const EmbreeHit& hit,
                                               const QueryContext& context,
                                               SurfaceInteraction* isect) const;
  // The interaction (in this aggregate's space) of the hit (primID, u, v, geometric normal ng)
  // on geometry g of this scene at ray parameter t. ray is the query's ray in this space;
  // shapeRay is the ray the Shapes callback accepted the hit on (QueryContext::shapeRay).
  bool interactionAt(const EmbreeGeometry& g, unsigned primID, float u, float v, const Vector3f& ng,
                     float t, const Ray& ray, const Ray& shapeRay, SurfaceInteraction* isect) const;

  const EmbreeDevice* device_;
  RTCSceneTy* scene_ = nullptr;
  int quality_;
  std::vector<std::unique_ptr<EmbreeGeometry>> geometries_;  // by geomID; stable user pointers
  std::vector<std::unique_ptr<EmbreeAggregate>> prototypes_;
  Bounds3f bounds_;
  long triangleGeometries_ = 0, userGeometries_ = 0, triangles_ = 0, userPrimitives_ = 0;
  long curveGeometries_ = 0, curves_ = 0;
  long instances_ = 0, instanceGeometries_ = 0, motionGeometries_ = 0, motionInstances_ = 0;
  bool packetQueries_ = false;  // no user geometry here or in a prototype (intersectCoherent)
};

}  // namespace candela
