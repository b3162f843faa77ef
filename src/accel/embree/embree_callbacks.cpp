// The user-geometry callbacks of the Embree aggregate: quadrics and other non-triangle shapes run
// their own intersection; animated instances transform the ray into the prototype's space at the
// ray's time and query the prototype's scene (pbrt 2e §4.1.2, TransformedPrimitive with an
// AnimatedTransform). Embree may call them with packets of N rays; the aggregate traces single
// rays only (rtcIntersect1, rtcOccluded1) in a scene that has them (its packets,
// intersectCoherent, are for scenes without user geometry), and the QueryContext notes rely on
// that.
#include "accel/embree/embree_geometry.h"

namespace candela {

namespace {

const EmbreeGeometry& geometryOf(const void* userPtr) {
  return *static_cast<const EmbreeGeometry*>(userPtr);
}

// Lane i of an N-wide Embree ray as one of ours, with tMax just above tfar so that the shape's
// open interval (0, tMax) matches Embree's closed [tnear, tfar].
Ray laneRay(RTCRayN* rays, unsigned N, unsigned i) {
  Point3f o(RTCRayN_org_x(rays, N, i), RTCRayN_org_y(rays, N, i), RTCRayN_org_z(rays, N, i));
  Vector3f d(RTCRayN_dir_x(rays, N, i), RTCRayN_dir_y(rays, N, i), RTCRayN_dir_z(rays, N, i));
  return Ray(o, d, nextFloatUp(RTCRayN_tfar(rays, N, i)), RTCRayN_time(rays, N, i));
}

void writeBounds(const Bounds3f& b, RTCBounds* out) {
  out->lower_x = b.pMin.x;
  out->lower_y = b.pMin.y;
  out->lower_z = b.pMin.z;
  out->upper_x = b.pMax.x;
  out->upper_y = b.pMax.y;
  out->upper_z = b.pMax.z;
}

// Records a hit of a user geometry in lane i. The interaction is computed for the closest hit
// only, after the query; Embree needs no normal or (u, v) here.
void acceptHit(const RTCIntersectFunctionNArguments* args, unsigned i, float t) {
  unsigned N = args->N;
  RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, N);
  RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, N);
  RTCRayN_tfar(rays, N, i) = t;
  RTCHitN_Ng_x(hits, N, i) = 0;
  RTCHitN_Ng_y(hits, N, i) = 0;
  RTCHitN_Ng_z(hits, N, i) = 0;
  RTCHitN_u(hits, N, i) = 0;
  RTCHitN_v(hits, N, i) = 0;
  RTCHitN_primID(hits, N, i) = args->primID;
  RTCHitN_geomID(hits, N, i) = args->geomID;
  RTCHitN_instID(hits, N, i, 0) = args->context->instID[0];
}

bool isFinite(const Matrix4x4& m) {
  for (const auto& row : m.m)
    for (Float v : row)
      if (!std::isfinite(v)) return false;
  return true;
}

// Lane i in the prototype's space at the ray's time, as an Embree ray over the same
// [tnear, tfar]: the maps are affine, so t means the same point in both spaces. False when the
// interpolated transform is singular at that time (the instance is flat then: no hit).
bool toPrototype(RTCRayN* rays, unsigned N, unsigned i, const AnimatedTransform& instanceToWorld,
                 Transform* toWorld, RTCRay* out) {
  Ray world = laneRay(rays, N, i);
  *toWorld = instanceToWorld.interpolate(world.time);
  if (!isFinite(toWorld->inverseMatrix())) return false;
  Transform toLocal = inverse(*toWorld);
  Point3f o = toLocal(world.o);
  Vector3f d = toLocal(world.d);
  if (!withinTraceableRange(o, d)) return false;
  toEmbreeRay(Ray(o, d, kInfinity, world.time), out);
  out->tnear = RTCRayN_tnear(rays, N, i);
  out->tfar = RTCRayN_tfar(rays, N, i);
  return true;
}

}  // namespace

void shapeBounds(const RTCBoundsFunctionArguments* args) {
  BoundsCallbackOrder order(args->geometryUserPtr);
  writeBounds(geometryOf(args->geometryUserPtr).primitive(args->primID).shape->worldBound(),
              args->bounds_o);
}

void shapeIntersect(const RTCIntersectFunctionNArguments* args) {
  const Shape* shape = geometryOf(args->geometryUserPtr).primitive(args->primID).shape;
  auto* context = reinterpret_cast<QueryContext*>(args->context);
  unsigned N = args->N;
  RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, N);
  for (unsigned i = 0; i < N; ++i) {
    if (args->valid[i] != -1) continue;
    Ray ray = laneRay(rays, N, i);
    Float t;
    if (!shape->intersect(ray, &t, nullptr) || t < RTCRayN_tnear(rays, N, i)) continue;
    acceptHit(args, i, t);
    context->shapeRay = ray;
  }
}

void shapeOccluded(const RTCOccludedFunctionNArguments* args) {
  const Shape* shape = geometryOf(args->geometryUserPtr).primitive(args->primID).shape;
  unsigned N = args->N;
  for (unsigned i = 0; i < N; ++i) {
    if (args->valid[i] != -1) continue;
    Ray ray = laneRay(args->ray, N, i);
    if (shape->intersectP(ray)) RTCRayN_tfar(args->ray, N, i) = -kInfinity;  // Embree's "occluded"
  }
}

void motionBounds(const RTCBoundsFunctionArguments* args) {
  BoundsCallbackOrder order(args->geometryUserPtr);
  writeBounds(geometryOf(args->geometryUserPtr).motion[args->primID].bound, args->bounds_o);
}

void motionIntersect(const RTCIntersectFunctionNArguments* args) {
  const EmbreeGeometry::Motion& m = geometryOf(args->geometryUserPtr).motion[args->primID];
  auto* context = reinterpret_cast<QueryContext*>(args->context);
  unsigned N = args->N;
  RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, N);
  for (unsigned i = 0; i < N; ++i) {
    if (args->valid[i] != -1) continue;
    RTCRayHit rh;
    Transform toWorld;
    if (!toPrototype(rays, N, i, *m.instanceToWorld, &toWorld, &rh.ray)) continue;
    rh.hit.geomID = rh.hit.primID = rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    // A query of its own, on another scene, from inside this callback: Embree 3 allows it.
    QueryContext inner;
    rtcIntersect1(m.scene, &inner.rtc, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
    acceptHit(args, i, rh.ray.tfar);
    PrototypeHit& note = context->motionHit.emplace();
    note.geomID = rh.hit.geomID;
    note.primID = rh.hit.primID;
    note.u = rh.hit.u;
    note.v = rh.hit.v;
    note.ng = Vector3f(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
    note.localRay = Ray(Point3f(rh.ray.org_x, rh.ray.org_y, rh.ray.org_z),
                        Vector3f(rh.ray.dir_x, rh.ray.dir_y, rh.ray.dir_z), kInfinity, rh.ray.time);
    note.shapeRay = inner.shapeRay;
    note.instanceToWorld = toWorld;
  }
}

void motionOccluded(const RTCOccludedFunctionNArguments* args) {
  const EmbreeGeometry::Motion& m = geometryOf(args->geometryUserPtr).motion[args->primID];
  unsigned N = args->N;
  for (unsigned i = 0; i < N; ++i) {
    if (args->valid[i] != -1) continue;
    RTCRay r;
    Transform toWorld;
    if (!toPrototype(args->ray, N, i, *m.instanceToWorld, &toWorld, &r)) continue;
    RTCIntersectContext inner;
    rtcInitIntersectContext(&inner);
    rtcOccluded1(m.scene, &inner, &r);
    if (r.tfar == -kInfinity) RTCRayN_tfar(args->ray, N, i) = -kInfinity;
  }
}

}  // namespace candela
