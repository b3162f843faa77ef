#include "accel/embree/embree_aggregate.h"

#include <map>

#include "accel/embree/embree_curves.h"
#include "accel/embree/embree_geometry.h"
#include "accel/embree/embree_triangle_filters.h"
#include "core/interaction_transform.h"
#include "shapes/triangle_mesh.h"

namespace candela {

namespace {

// Rays Embree must never see: it asserts on components beyond its range (core/ray.h).
bool isTraceable(const Ray& ray) {
  return withinTraceableRange(ray.o, ray.d) && ray.d != Vector3f() && ray.tMax > 0;
}

Vector3f hitNormal(const RTCHit& h) { return Vector3f(h.Ng_x, h.Ng_y, h.Ng_z); }

RTCBuildQuality embreeQuality(int q) {
  return q == int(EmbreeAggregate::BuildQuality::High) ? RTC_BUILD_QUALITY_HIGH
                                                       : RTC_BUILD_QUALITY_MEDIUM;
}

}  // namespace

EmbreeAggregate::EmbreeAggregate(const EmbreeDevice& device,
                                 const std::vector<Primitive>& primitives, BuildQuality quality)
    : EmbreeAggregate(device, primitives.data(), primitives.size(), nullptr, quality) {}

EmbreeAggregate::EmbreeAggregate(const EmbreeDevice& device, const SceneGeometry& geometry,
                                 BuildQuality quality)
    : EmbreeAggregate(device, geometry.primitives.data(), geometry.primitives.size(), &geometry,
                      quality) {}

EmbreeAggregate::EmbreeAggregate(const EmbreeDevice& device, const Primitive* primitives,
                                 size_t count, const SceneGeometry* geometry, BuildQuality quality)
    : device_(&device), quality_(int(quality)) {
  scene_ = rtcNewScene(device_->handle());
  device_->check("rtcNewScene");
  try {
    // Robust traversal: no misses through edges and vertices for extreme ray directions.
    rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene_, embreeQuality(quality_));
    addPrimitives(primitives, count);
    if (geometry) addInstances(*geometry);
    for (const auto& g : geometries_) releaseOrder(g.get());  // BoundsCallbackOrder
    rtcCommitScene(scene_);
    for (const auto& g : geometries_) acquireOrder(boundsDoneAddress(g.get()));
    device_->check("rtcCommitScene");
    packetQueries_ = userGeometries_ == 0 && motionGeometries_ == 0;
    for (const auto& p : prototypes_) packetQueries_ = packetQueries_ && p->packetQueries_;
  } catch (...) {
    rtcReleaseScene(scene_);
    throw;
  }
  if (!geometries_.empty()) {
    RTCBounds b;
    rtcGetSceneBounds(scene_, &b);
    if (b.lower_x <= b.upper_x)
      bounds_ = Bounds3f(Point3f(b.lower_x, b.lower_y, b.lower_z),
                         Point3f(b.upper_x, b.upper_y, b.upper_z));
  }
}

EmbreeAggregate::~EmbreeAggregate() {
  // The scene goes before the prototypes' scenes it instances (Embree counts references, so
  // either order is safe; this one reads naturally).
  if (scene_) rtcReleaseScene(scene_);
}

unsigned EmbreeAggregate::attach(RTCGeometry g, std::unique_ptr<EmbreeGeometry> info) {
  rtcSetGeometryBuildQuality(g, embreeQuality(quality_));
  rtcSetGeometryUserData(g, info.get());
  rtcCommitGeometry(g);
  unsigned id = rtcAttachGeometry(scene_, g);
  rtcReleaseGeometry(g);
  device_->check("creating an Embree geometry");
  if (id != geometries_.size()) throw EmbreeError("Embree: unexpected geometry ID");
  geometries_.push_back(std::move(info));
  return id;
}

void EmbreeAggregate::addPrimitives(const Primitive* primitives, size_t n) {
  RTCDevice dev = device_->handle();
  auto userPrims = std::make_unique<EmbreeGeometry>();
  userPrims->kind = EmbreeGeometry::Kind::Shapes;
  userPrims->primitives = primitives;
  for (size_t i = 0; i < n;) {
    const Shape* shape = primitives[i].shape;
    if (const auto* curve = dynamic_cast<const CurveShape*>(shape)) {
      // The run of consecutive curve pieces of one type: one native curve geometry.
      CurveType type = curve->piece().type;
      auto info = std::make_unique<EmbreeGeometry>();
      info->kind = EmbreeGeometry::Kind::Curves;
      info->primitives = primitives;
      for (; i < n; ++i) {
        const auto* c = dynamic_cast<const CurveShape*>(primitives[i].shape);
        if (!c || c->piece().type != type) break;
        info->primIndex.push_back(uint32_t(i));
      }
      RTCGeometry g = newCurveGeometry(dev, type, primitives, info->primIndex);
      device_->check("creating an Embree curve geometry");
      if (!g) throw EmbreeError("Embree: could not create a curve geometry");
      curves_ += long(info->primIndex.size());
      ++curveGeometries_;
      attach(g, std::move(info));
      continue;
    }
    int tri = 0;
    const TriangleMesh* mesh = shape ? shape->triangleMesh(&tri) : nullptr;
    if (!mesh || !dynamic_cast<const TriangleShape*>(shape)) {
      if (shape) userPrims->primIndex.push_back(uint32_t(i));
      ++i;
      continue;
    }
    // The run of consecutive triangles of this mesh: one native triangle geometry, with the
    // mesh's vertices (world space, or the prototype's space in a prototype).
    auto info = std::make_unique<EmbreeGeometry>();
    info->kind = EmbreeGeometry::Kind::Triangles;
    info->primitives = primitives;
    std::vector<unsigned> indices;
    const int firstTriangle = tri;
    bool inMeshOrder = true;
    for (; i < n; ++i) {
      const Shape* s = primitives[i].shape;
      if (!s || s->triangleMesh(&tri) != mesh || !dynamic_cast<const TriangleShape*>(s)) break;
      for (int k = 0; k < 3; ++k) indices.push_back(unsigned(mesh->indices[3 * tri + k]));
      inMeshOrder = inMeshOrder && tri == firstTriangle + int(info->primIndex.size());
      info->primIndex.push_back(uint32_t(i));
    }
    if (inMeshOrder) {
      info->mesh = mesh;
      info->firstTriangle = firstTriangle;
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
    setTriangleFilters(g, *mesh);  // alpha cut-outs and degenerate triangles, where present
    triangles_ += long(info->primIndex.size());
    ++triangleGeometries_;
    attach(g, std::move(info));
  }
  if (!userPrims->primIndex.empty()) {
    RTCGeometry g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(g, unsigned(userPrims->primIndex.size()));
    rtcSetGeometryBoundsFunction(g, shapeBounds, nullptr);
    rtcSetGeometryIntersectFunction(g, shapeIntersect);
    rtcSetGeometryOccludedFunction(g, shapeOccluded);
    userPrimitives_ = long(userPrims->primIndex.size());
    ++userGeometries_;
    attach(g, std::move(userPrims));
  }
}

void EmbreeAggregate::addInstances(const SceneGeometry& geometry) {
  RTCDevice dev = device_->handle();
  // Each prototype's scene is built once, on its first use, and shared by all its instances.
  std::map<const InstancePrototype*, const EmbreeAggregate*> built;
  auto prototypeOf = [&](const InstancePrototype* p) -> const EmbreeAggregate* {
    if (!p || p->primitives.empty()) return nullptr;
    if (auto it = built.find(p); it != built.end()) return it->second;
    prototypes_.push_back(std::unique_ptr<EmbreeAggregate>(new EmbreeAggregate(
        *device_, p->primitives.data(), p->primitives.size(), nullptr, BuildQuality(quality_))));
    return built[p] = prototypes_.back().get();
  };

  auto motion = std::make_unique<EmbreeGeometry>();
  motion->kind = EmbreeGeometry::Kind::MotionInstances;
  for (const Instance& inst : geometry.instances) {
    const EmbreeAggregate* proto = prototypeOf(inst.prototype);
    if (!proto) continue;
    ++instances_;
    if (inst.instanceToWorld.isAnimated()) {
      motion->motion.push_back({proto, proto->scene_, &inst.instanceToWorld,
                                inst.instanceToWorld.motionBounds(proto->bounds_)});
      continue;
    }
    const Transform& t = inst.instanceToWorld.start();
    RTCGeometry g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(g, proto->scene_);
    float rows[12];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 4; ++j) rows[4 * i + j] = t.matrix().m[i][j];
    rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, rows);
    auto info = std::make_unique<EmbreeGeometry>();
    info->kind = EmbreeGeometry::Kind::Instance;
    info->prototype = proto;
    info->instanceToWorld = &t;
    ++instanceGeometries_;
    attach(g, std::move(info));
  }
  if (!motion->motion.empty()) {
    RTCGeometry g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(g, unsigned(motion->motion.size()));
    rtcSetGeometryBoundsFunction(g, motionBounds, nullptr);
    rtcSetGeometryIntersectFunction(g, motionIntersect);
    rtcSetGeometryOccludedFunction(g, motionOccluded);
    motionInstances_ = long(motion->motion.size());
    ++motionGeometries_;
    attach(g, std::move(motion));
  }
}

// Inline: every closest hit goes through it.
inline bool EmbreeAggregate::interactionAt(const EmbreeGeometry& g, unsigned primID, float u,
                                           float v, const Vector3f& ng, float t, const Ray& ray,
                                           const Ray& shapeRay, SurfaceInteraction* isect) const {
  const Primitive& prim = g.primitive(primID);
  if (g.kind == EmbreeGeometry::Kind::Curves) {
    // Embree's u runs along the piece; its v and, for flat curves, Ng (the tangent there) are
    // of no use: the curve computes v and the normal itself.
    const auto* curve = static_cast<const CurveShape*>(prim.shape);
    *isect = curve->interactionAt(ray, u, t, ng);
  } else if (g.kind == EmbreeGeometry::Kind::Shapes) {
    // The shape's own intersection again, on the very ray its callback accepted the hit on,
    // limited to just past the hit: it is deterministic, so it finds the same t, now with the
    // full interaction.
    Ray clipped = shapeRay;
    clipped.tMax = nextFloatUp(t);
    Float tHit;
    if (!prim.shape->intersect(clipped, &tHit, isect)) return false;
  } else if (g.mesh) {
    // Embree's (u, v) are the barycentrics of vertices 1 and 2.
    TriangleShape::interactionAt(*g.mesh, g.firstTriangle + int(primID), ray, u, v, isect);
  } else {
    const auto* tri = static_cast<const TriangleShape*>(prim.shape);
    tri->interactionAt(ray, u, v, t, isect);
  }
  isect->primitive = &prim;
  return true;
}

// Inline: every closest hit goes through it.
inline bool EmbreeAggregate::finishHit(const Ray& ray, const EmbreeHit& hit,
                                       const QueryContext& context,
                                       SurfaceInteraction* isect) const {
  if (hit.instID != RTC_INVALID_GEOMETRY_ID) {
    // A static instance: the hit is on the prototype's geometry geomID; the interaction is
    // found in the prototype's space and carried to world space (lrt draft §4.1.2).
    const EmbreeGeometry& inst = *geometries_[hit.instID];
    const EmbreeAggregate& proto = *inst.prototype;
    // The ray as Embree took it into the prototype (the same t means the same point).
    Transform toLocal = inverse(*inst.instanceToWorld);
    Ray local(toLocal(ray.o), toLocal(ray.d), ray.tMax, ray.time);
    if (!proto.interactionAt(*proto.geometries_[hit.geomID], hit.primID, hit.u, hit.v, hit.ng,
                             hit.t, local, context.shapeRay, isect))
      return false;
    *isect = transformSurfaceInteraction(*inst.instanceToWorld, *isect, ray.d);
  } else if (const EmbreeGeometry& g = *geometries_[hit.geomID];
             g.kind == EmbreeGeometry::Kind::MotionInstances) {
    const PrototypeHit& h = *context.motionHit;  // the callback that accepted the hit made it
    const EmbreeAggregate& proto = *g.motion[hit.primID].prototype;
    if (!proto.interactionAt(*proto.geometries_[h.geomID], h.primID, h.u, h.v, h.ng, hit.t,
                             h.localRay, h.shapeRay, isect))
      return false;
    *isect = transformSurfaceInteraction(h.instanceToWorld, *isect, ray.d);
  } else {
    if (!interactionAt(g, hit.primID, hit.u, hit.v, hit.ng, hit.t, ray, context.shapeRay, isect))
      return false;
  }
  ray.tMax = hit.t;
  return true;
}

bool EmbreeAggregate::intersect(const Ray& ray, SurfaceInteraction* isect) const {
  if (!isTraceable(ray)) return false;
  QueryContext context;
  RTCRayHit rh;
  toEmbreeRay(ray, &rh.ray);
  rh.hit.geomID = rh.hit.primID = rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context.rtc, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
  EmbreeHit hit{rh.hit.geomID, rh.hit.primID,     rh.hit.instID[0], rh.hit.u,
                rh.hit.v,      hitNormal(rh.hit), rh.ray.tfar};
  return finishHit(ray, hit, context, isect);
}

void EmbreeAggregate::intersectCoherent(std::span<const Ray> rays, SurfaceInteraction* isects,
                                        bool* hits) const {
  // Packets need callbacks that take them: the user geometries' (quadrics, animated instances)
  // take one ray at a time.
  if (!packetQueries_) return Aggregate::intersectCoherent(rays, isects, hits);
  for (size_t first = 0; first < rays.size(); first += 8) {
    const size_t n = std::min<size_t>(8, rays.size() - first);
    alignas(32) int valid[8];
    RTCRayHit8 rh;
    for (size_t i = 0; i < 8; ++i) {
      const bool traced = i < n && isTraceable(rays[first + i]);
      valid[i] = traced ? -1 : 0;
      RTCRay r;
      toEmbreeRay(traced ? rays[first + i] : Ray(), &r);
      rh.ray.org_x[i] = r.org_x;
      rh.ray.org_y[i] = r.org_y;
      rh.ray.org_z[i] = r.org_z;
      rh.ray.dir_x[i] = r.dir_x;
      rh.ray.dir_y[i] = r.dir_y;
      rh.ray.dir_z[i] = r.dir_z;
      rh.ray.tnear[i] = r.tnear;
      rh.ray.tfar[i] = r.tfar;
      rh.ray.time[i] = r.time;
      rh.ray.mask[i] = r.mask;
      rh.ray.id[i] = r.id;
      rh.ray.flags[i] = r.flags;
      rh.hit.geomID[i] = rh.hit.primID[i] = rh.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
    }
    QueryContext context;
    context.rtc.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    rtcIntersect8(valid, scene_, &context.rtc, &rh);
    for (size_t i = 0; i < n; ++i) {
      bool hit = valid[i] && rh.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID;
      if (hit) {
        EmbreeHit h{rh.hit.geomID[i],    rh.hit.primID[i],
                    rh.hit.instID[0][i], rh.hit.u[i],
                    rh.hit.v[i],         Vector3f(rh.hit.Ng_x[i], rh.hit.Ng_y[i], rh.hit.Ng_z[i]),
                    rh.ray.tfar[i]};
        hit = finishHit(rays[first + i], h, context, &isects[first + i]);
      }
      hits[first + i] = hit;
    }
  }
}

bool EmbreeAggregate::intersectP(const Ray& ray) const {
  if (!isTraceable(ray)) return false;
  RTCIntersectContext context;  // no callback of a shadow query leaves notes (QueryContext)
  rtcInitIntersectContext(&context);
  RTCRay r;
  toEmbreeRay(ray, &r);
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
  if (curves_ > 0) {
    s.counts["embree curve geometries"] = curveGeometries_;
    s.counts["curves"] = curves_;
  }
  if (instances_ > 0) {
    long protoTriangles = 0, protoUser = 0;
    for (const auto& p : prototypes_) {
      protoTriangles += p->triangles_;
      protoUser += p->userPrimitives_;
    }
    s.counts["instances"] = instances_;
    s.counts["prototypes"] = long(prototypes_.size());
    s.counts["embree instance geometries"] = instanceGeometries_;
    s.counts["embree motion user geometries"] = motionGeometries_;
    s.counts["motion instances"] = motionInstances_;
    s.counts["prototype triangles"] = protoTriangles;
    s.counts["prototype user primitives"] = protoUser;
  }
  return s;
}

}  // namespace candela
