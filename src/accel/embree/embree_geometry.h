// Internal to the Embree aggregate: what each Embree geometry stands for, the query context its
// callbacks write to, and the callbacks themselves. Only src/accel/embree includes this (and the
// render benchmark's Embree ceiling, which converts rays as the aggregate does).
#pragma once

#include <embree3/rtcore.h>

#include <cstdint>
#include <optional>
#include <vector>

#include "accel/primitive.h"
#include "core/animated_transform.h"
#include "core/happens_before.h"

namespace candela {

class EmbreeAggregate;
struct TriangleMesh;

// Embree's t interval is closed, [tnear, tfar]; ours is open, (0, tMax). The smallest normal
// float as tnear drops hits at exactly t = 0 (an origin on a triangle's plane: Embree's test
// accepts tnear <= t) and is unaffected by denormals-are-zero.
inline constexpr float kEmbreeTNear = std::numeric_limits<float>::min();

// One geometry of an Embree scene.
struct EmbreeGeometry {
  enum class Kind : uint8_t {
    Triangles,       // native triangles of one mesh: primID -> primitives[primIndex[primID]]
    Shapes,          // user geometry of quadrics etc., likewise through primIndex
    Curves,          // native curves of CurveShapes of one type, likewise through primIndex
    Instance,        // a static instance of a prototype's scene (RTC_GEOMETRY_TYPE_INSTANCE)
    MotionInstances  // user geometry: primID -> motion[primID], an animated instance
  };
  // An instance whose transform changes over the shutter: the callbacks transform each ray by
  // the inverse of the transform at the ray's time and query the prototype's own scene.
  struct Motion {
    const EmbreeAggregate* prototype;
    RTCScene scene;                            // the prototype's
    const AnimatedTransform* instanceToWorld;  // owned by the SceneGeometry
    Bounds3f bound;                            // world bound over the whole interval
  };

  Kind kind = Kind::Triangles;
  const Primitive* primitives = nullptr;       // Triangles, Shapes, Curves: the primitives
  std::vector<uint32_t> primIndex;             // Triangles, Shapes, Curves
  const EmbreeAggregate* prototype = nullptr;  // Instance
  const Transform* instanceToWorld = nullptr;  // Instance; owned by the SceneGeometry
  std::vector<Motion> motion;                  // MotionInstances
  // Triangles whose primIDs are their mesh's triangles firstTriangle + primID: a hit's vertices
  // found from the mesh, in fewer dependent loads than through its primitive and shape.
  const TriangleMesh* mesh = nullptr;
  int firstTriangle = 0;

  const Primitive& primitive(unsigned primID) const { return primitives[primIndex[primID]]; }
};

// A hit found by a motion callback inside a prototype's scene, kept for the closest-hit
// interaction: the prototype's hit record, the ray as the prototype saw it, and the transform
// at the ray's time.
struct PrototypeHit {
  unsigned geomID = RTC_INVALID_GEOMETRY_ID, primID = RTC_INVALID_GEOMETRY_ID;
  float u = 0, v = 0;
  Vector3f ng;   // Embree's geometric normal, in the prototype's space
  Ray localRay;  // the query's ray in the prototype's space
  Ray shapeRay;  // the prototype query's own QueryContext::shapeRay
  Transform instanceToWorld;
};

// Embree hands the context pointer given to rtcIntersect1 unchanged to every callback of the
// query, also inside instances (the pattern Embree documents for per-query data), so the
// callbacks can leave notes here. A callback that accepts a hit overwrites the ray's tfar and
// hit record, and any later hit must be closer, so the final hit is the last one written: the
// notes of the last writer of each kind are the ones that belong to the final hit.
// Shadow queries leave no notes: they use a bare RTCIntersectContext.
struct QueryContext {
  RTCIntersectContext rtc;  // must stay the first member: Embree sees only this
  // The ray (in the space of its geometry) on which a Shapes callback last accepted a hit.
  // Re-running the shape's intersection on exactly this ray gives exactly the same t.
  Ray shapeRay;
  // The last hit accepted by a MotionInstances callback; made by that callback, since building
  // one (two rays and a transform) for every query would cost more than most queries' own work.
  std::optional<PrototypeHit> motionHit;
  QueryContext() { rtcInitIntersectContext(&rtc); }
};

// The ray as Embree wants it, over (0, tMax). Inline: every query makes one.
inline void toEmbreeRay(const Ray& ray, RTCRay* r) {
  r->org_x = ray.o.x;
  r->org_y = ray.o.y;
  r->org_z = ray.o.z;
  r->dir_x = ray.d.x;
  r->dir_y = ray.d.y;
  r->dir_z = ray.d.z;
  r->tnear = kEmbreeTNear;
  // Closed on Embree's side: the float just below tMax keeps tMax itself out.
  r->tfar = nextFloatDown(ray.tMax);
  r->time = ray.time;
  r->mask = 0xFFFFFFFFu;
  r->id = 0;
  r->flags = 0;
}

// A scene build runs the bounds callbacks on TBB's threads inside Embree; its two orders, declared
// to ThreadSanitizer (core/happens_before.h): the geometry as attached happens before each
// callback (address: the geometry's), each callback before rtcCommitScene returns (address: the
// byte after it, so that the callbacks are not ordered with each other).
inline const void* boundsDoneAddress(const void* geometry) {
  return static_cast<const char*>(geometry) + 1;
}
struct BoundsCallbackOrder {
  const void* geometry;
  explicit BoundsCallbackOrder(const void* g) : geometry(g) { acquireOrder(g); }
  ~BoundsCallbackOrder() { releaseOrder(boundsDoneAddress(geometry)); }
};

// Callbacks for Kind::Shapes (user data: the EmbreeGeometry).
void shapeBounds(const RTCBoundsFunctionArguments* args);
void shapeIntersect(const RTCIntersectFunctionNArguments* args);
void shapeOccluded(const RTCOccludedFunctionNArguments* args);

// Callbacks for Kind::MotionInstances (user data: the EmbreeGeometry).
void motionBounds(const RTCBoundsFunctionArguments* args);
void motionIntersect(const RTCIntersectFunctionNArguments* args);
void motionOccluded(const RTCOccludedFunctionNArguments* args);

}  // namespace candela
