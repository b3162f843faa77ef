#include "accel/embree/embree_aggregate.h"

#include <embree3/rtcore.h>

#include "shapes/triangle_mesh.h"

namespace candela {

namespace {

using Geometry = EmbreeAggregate::Geometry;

// Embree's t interval is closed, [tnear, tfar]; ours is open, (0, tMax). The smallest normal
// float as tnear drops hits at exactly t = 0 (an origin on a triangle's plane: Embree's test
// accepts tnear <= t) and is unaffected by denormals-are-zero.
constexpr float kTNear = std::numeric_limits<float>::min();

bool isFinite(const Point3f& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}
bool isFinite(const Vector3f& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Rays Embree must never see: its traversal assumes finite origins and directions.
bool isTraceable(const Ray& ray) {
  return isFinite(ray.o) && isFinite(ray.d) && ray.d != Vector3f() && ray.tMax > 0;
}

void toEmbree(const Ray& ray, RTCRay* r) {
  r->org_x = ray.o.x;
  r->org_y = ray.o.y;
  r->org_z = ray.o.z;
  r->dir_x = ray.d.x;
  r->dir_y = ray.d.y;
  r->dir_z = ray.d.z;
  r->tnear = kTNear;
  // Closed on Embree's side: the float just below tMax keeps tMax itself out.
  r->tfar = nextFloatDown(ray.tMax);
  r->time = ray.time;
  r->mask = 0xFFFFFFFFu;
  r->id = 0;
  r->flags = 0;
}

// Lane i of an N-wide Embree ray as one of ours, with tMax just above tfar so that the shape's
// open interval (0, tMax) matches Embree's closed [tnear, tfar].
Ray laneRay(RTCRayN* rays, unsigned N, unsigned i) {
  Point3f o(RTCRayN_org_x(rays, N, i), RTCRayN_org_y(rays, N, i), RTCRayN_org_z(rays, N, i));
  Vector3f d(RTCRayN_dir_x(rays, N, i), RTCRayN_dir_y(rays, N, i), RTCRayN_dir_z(rays, N, i));
  return Ray(o, d, nextFloatUp(RTCRayN_tfar(rays, N, i)), RTCRayN_time(rays, N, i));
}

const Shape* userShape(const void* userPtr, unsigned primID) {
  const auto* g = static_cast<const Geometry*>(userPtr);
  return g->primitives[g->primIndex[primID]].shape;
}

// User geometry callbacks. Embree may call them with packets of N rays (N = 1 for the
// rtcIntersect1/rtcOccluded1 we use); lanes whose valid[] is not -1 are inactive.
void userBounds(const RTCBoundsFunctionArguments* args) {
  Bounds3f b = userShape(args->geometryUserPtr, args->primID)->worldBound();
  RTCBounds* out = args->bounds_o;
  out->lower_x = b.pMin.x;
  out->lower_y = b.pMin.y;
  out->lower_z = b.pMin.z;
  out->upper_x = b.pMax.x;
  out->upper_y = b.pMax.y;
  out->upper_z = b.pMax.z;
}

void userIntersect(const RTCIntersectFunctionNArguments* args) {
  const Shape* shape = userShape(args->geometryUserPtr, args->primID);
  unsigned N = args->N;
  RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, N);
  RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, N);
  for (unsigned i = 0; i < N; ++i) {
    if (args->valid[i] != -1) continue;
    Ray ray = laneRay(rays, N, i);
    Float t;
    if (!shape->intersect(ray, &t, nullptr) || t < RTCRayN_tnear(rays, N, i)) continue;
    RTCRayN_tfar(rays, N, i) = t;
    // The interaction is recomputed for the closest hit only, after the query; Embree needs
    // no normal or (u, v) here.
    RTCHitN_Ng_x(hits, N, i) = 0;
    RTCHitN_Ng_y(hits, N, i) = 0;
    RTCHitN_Ng_z(hits, N, i) = 0;
    RTCHitN_u(hits, N, i) = 0;
    RTCHitN_v(hits, N, i) = 0;
    RTCHitN_primID(hits, N, i) = args->primID;
    RTCHitN_geomID(hits, N, i) = args->geomID;
    RTCHitN_instID(hits, N, i, 0) = args->context->instID[0];
  }
}

void userOccluded(const RTCOccludedFunctionNArguments* args) {
  const Shape* shape = userShape(args->geometryUserPtr, args->primID);
  unsigned N = args->N;
  for (unsigned i = 0; i < N; ++i) {
    if (args->valid[i] != -1) continue;
    Ray ray = laneRay(args->ray, N, i);
    if (shape->intersectP(ray)) RTCRayN_tfar(args->ray, N, i) = -kInfinity;  // Embree's "occluded"
  }
}

}  // namespace

EmbreeAggregate::EmbreeAggregate(const EmbreeDevice& device,
                                 const std::vector<Primitive>& primitives, BuildQuality quality)
    : device_(&device), primitives_(primitives.data()) {
  RTCDevice dev = device_->handle();
  RTCBuildQuality q =
      quality == BuildQuality::High ? RTC_BUILD_QUALITY_HIGH : RTC_BUILD_QUALITY_MEDIUM;
  scene_ = rtcNewScene(dev);
  device_->check("rtcNewScene");
  try {
    // Robust traversal: no misses through edges and vertices for extreme ray directions.
    rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene_, q);
    auto attach = [&](RTCGeometry g, std::unique_ptr<Geometry> info) {
      rtcSetGeometryBuildQuality(g, q);
      if (info->isUser) rtcSetGeometryUserData(g, info.get());
      rtcCommitGeometry(g);
      unsigned id = rtcAttachGeometry(scene_, g);
      rtcReleaseGeometry(g);
      device_->check("creating an Embree geometry");
      if (id != geometries_.size()) throw EmbreeError("Embree: unexpected geometry ID");
      geometries_.push_back(std::move(info));
    };

    auto userPrims = std::make_unique<Geometry>();
    userPrims->isUser = true;
    userPrims->primitives = primitives_;
    size_t n = primitives.size();
    for (size_t i = 0; i < n;) {
      const Shape* shape = primitives[i].shape;
      int tri = 0;
      const TriangleMesh* mesh = shape ? shape->triangleMesh(&tri) : nullptr;
      if (!mesh || !dynamic_cast<const TriangleShape*>(shape)) {
        if (shape) userPrims->primIndex.push_back(uint32_t(i));
        ++i;
        continue;
      }
      // The run of consecutive triangles of this mesh: one native triangle geometry, with the
      // mesh's world-space vertices.
      auto info = std::make_unique<Geometry>();
      info->primitives = primitives_;
      std::vector<unsigned> indices;
      for (; i < n; ++i) {
        const Shape* s = primitives[i].shape;
        if (!s || s->triangleMesh(&tri) != mesh || !dynamic_cast<const TriangleShape*>(s)) break;
        for (int k = 0; k < 3; ++k) indices.push_back(unsigned(mesh->indices[3 * tri + k]));
        info->primIndex.push_back(uint32_t(i));
      }
      RTCGeometry g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_TRIANGLE);
      // Embree may read 16 bytes at the last vertex; its own buffers are padded for that.
      auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(
          g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh->p.size()));
      auto* ib = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
          g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), indices.size() / 3));
      device_->check("allocating Embree triangle buffers");
      for (size_t v = 0; v < mesh->p.size(); ++v) {
        vb[3 * v + 0] = mesh->p[v].x;
        vb[3 * v + 1] = mesh->p[v].y;
        vb[3 * v + 2] = mesh->p[v].z;
      }
      std::copy(indices.begin(), indices.end(), ib);
      triangles_ += long(info->primIndex.size());
      ++triangleGeometries_;
      attach(g, std::move(info));
    }
    if (!userPrims->primIndex.empty()) {
      RTCGeometry g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_USER);
      rtcSetGeometryUserPrimitiveCount(g, unsigned(userPrims->primIndex.size()));
      rtcSetGeometryBoundsFunction(g, userBounds, nullptr);
      rtcSetGeometryIntersectFunction(g, userIntersect);
      rtcSetGeometryOccludedFunction(g, userOccluded);
      userPrimitives_ = long(userPrims->primIndex.size());
      ++userGeometries_;
      attach(g, std::move(userPrims));
    }
    rtcCommitScene(scene_);
    device_->check("rtcCommitScene");
  } catch (...) {
    rtcReleaseScene(scene_);
    throw;
  }
  if (!primitives.empty()) {
    RTCBounds b;
    rtcGetSceneBounds(scene_, &b);
    if (b.lower_x <= b.upper_x)
      bounds_ = Bounds3f(Point3f(b.lower_x, b.lower_y, b.lower_z),
                         Point3f(b.upper_x, b.upper_y, b.upper_z));
  }
}

EmbreeAggregate::~EmbreeAggregate() {
  if (scene_) rtcReleaseScene(scene_);
}

bool EmbreeAggregate::intersect(const Ray& ray, SurfaceInteraction* isect) const {
  if (!isTraceable(ray)) return false;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh;
  toEmbree(ray, &rh.ray);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;

  const Geometry& g = *geometries_[rh.hit.geomID];
  const Primitive& prim = primitives_[g.primIndex[rh.hit.primID]];
  if (g.isUser) {
    // The shape's own intersection again, on the same ray limited to just past the hit: it is
    // deterministic, so it finds the same t, now with the full interaction.
    Ray clipped = ray;
    clipped.tMax = nextFloatUp(rh.ray.tfar);
    Float t;
    if (!prim.shape->intersect(clipped, &t, isect)) return false;
    ray.tMax = t;
  } else {
    // Embree's (u, v) are the barycentrics of vertices 1 and 2.
    const auto* tri = static_cast<const TriangleShape*>(prim.shape);
    *isect = tri->interactionAt(ray, rh.hit.u, rh.hit.v, rh.ray.tfar);
    ray.tMax = rh.ray.tfar;
  }
  isect->primitive = &prim;
  return true;
}

bool EmbreeAggregate::intersectP(const Ray& ray) const {
  if (!isTraceable(ray)) return false;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay r;
  toEmbree(ray, &r);
  rtcOccluded1(scene_, &context, &r);
  return r.tfar == -kInfinity;
}

AggregateStats EmbreeAggregate::stats() const {
  AggregateStats s;
  s.name = "embree";
  s.counts["embree triangle geometries"] = triangleGeometries_;
  s.counts["embree user geometries"] = userGeometries_;
  s.counts["triangles"] = triangles_;
  s.counts["user primitives"] = userPrimitives_;
  return s;
}

}  // namespace candela
