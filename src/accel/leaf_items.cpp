#include "accel/leaf_items.h"

#include <map>

#include "accel/ray_query.h"
#include "core/interaction_transform.h"

namespace candela {

namespace {

// A world ray in instance space. The transformed origin carries rounding error oError; it is
// moved forward along d to the edge of that error box, so that a ray spawned from a surface in
// world space cannot start behind that surface in instance space (pbrt 3e §3.9.4). *dt is that
// move, in units of the ray parameter, which is otherwise the same in both spaces (the map is
// affine and d is not renormalised).
Ray toInstance(const Transform& worldToInstance, const Ray& ray, Float* dt) {
  Vector3f oError;
  Point3f o = worldToInstance.apply(ray.o, &oError);
  Vector3f d = worldToInstance(ray.d);
  *dt = 0;
  Float l2 = d.lengthSquared();
  if (l2 > 0) *dt = dot(abs(d), oError) / l2;
  return Ray(o + d * *dt, d, ray.tMax - *dt, ray.time);
}

}  // namespace

LeafItems::LeafItems(std::span<const Primitive> primitives)
    : primitives_(primitives.data()), nPrimitives_(uint32_t(primitives.size())) {}

LeafItems::LeafItems(const SceneGeometry& geometry, const PrototypeBuilder& buildPrototype)
    : LeafItems(std::span<const Primitive>(geometry.primitives)) {
  // One sub-aggregate per prototype, built on first use and shared by all its instances.
  std::map<const InstancePrototype*, const Aggregate*> built;
  for (const Instance& inst : geometry.instances) {
    const InstancePrototype* proto = inst.prototype;
    if (!proto || proto->primitives.empty()) continue;
    const Aggregate*& sub = built[proto];
    if (!sub) {
      prototypes_.push_back(buildPrototype(std::span<const Primitive>(proto->primitives)));
      sub = prototypes_.back().get();
    }
    Bounds3f b = sub->worldBound();
    if (b.empty()) continue;
    InstanceItem item;
    item.prototype = sub;
    item.instanceToWorld = &inst.instanceToWorld;
    item.worldToInstance = inverse(inst.instanceToWorld.start());
    item.worldBound =
        padBound(inst.instanceToWorld.isAnimated() ? inst.instanceToWorld.motionBounds(b)
                                                   : inst.instanceToWorld.start()(b));
    instances_.push_back(item);
  }
}

Bounds3f LeafItems::bound(uint32_t i) const {
  if (i < nPrimitives_) {
    const Shape* s = primitives_[i].shape;
    return s ? padBound(s->worldBound()) : Bounds3f();
  }
  return instances_[i - nPrimitives_].worldBound;
}

bool LeafItems::intersectInstance(const InstanceItem& inst, const Ray& ray,
                                  SurfaceInteraction* isect) const {
  // An animated instance is placed at the ray's time (lrt draft §2.7 scaffolding, interpolated
  // as AnimatedTransform describes); a static one uses the inverse computed once.
  Transform animated;
  const Transform* w2i = &inst.worldToInstance;
  if (inst.instanceToWorld->isAnimated()) {
    animated = inverse(inst.instanceToWorld->interpolate(ray.time));
    w2i = &animated;
  }
  Float dt;
  Ray r = toInstance(*w2i, ray, &dt);
  if (!inst.prototype->intersect(r, isect)) return false;
  // Back to the world ray's parameter; rounding may not carry it to tMax or past it.
  Float t = r.tMax + dt;
  ray.tMax = t < ray.tMax ? t : nextFloatDown(ray.tMax);
  // Shared with the Embree aggregate, so both report the same interaction for the same hit.
  *isect = transformSurfaceInteraction(inverse(*w2i), *isect, ray.d);
  return true;
}

bool LeafItems::intersectInstanceP(const InstanceItem& inst, const Ray& ray) const {
  Transform animated;
  const Transform* w2i = &inst.worldToInstance;
  if (inst.instanceToWorld->isAnimated()) {
    animated = inverse(inst.instanceToWorld->interpolate(ray.time));
    w2i = &animated;
  }
  Float dt;
  return inst.prototype->intersectP(toInstance(*w2i, ray, &dt));
}

long LeafItems::bytes() const {
  long b = long(instances_.capacity() * sizeof(InstanceItem) +
                prototypes_.capacity() * sizeof(std::unique_ptr<Aggregate>));
  for (const auto& p : prototypes_) {
    AggregateStats s = p->stats();
    if (auto it = s.counts.find("bytes"); it != s.counts.end()) b += it->second;
  }
  return b;
}

}  // namespace candela
