// What the leaves of the reference aggregates (grid, kd-tree, BVH) point to: world-space
// primitives and instances. An instance is a prototype's own sub-aggregate (built once, of the
// same kind, shared by every instance of the prototype) seen through the instance's transform:
// the lrt draft's InstancePrimitive (§4.1.2), with the transform possibly animated.
//
// The spatial structures see items only as an index, a bound and an intersection routine, so
// grid, kd-tree and BVH hold primitives and instances alike.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "accel/aggregate.h"
#include "accel/scene_geometry.h"

namespace candela {

class LeafItems {
 public:
  // Builds the sub-aggregate of one prototype (from its primitives, in its own space).
  using PrototypeBuilder =
      std::function<std::unique_ptr<Aggregate>(std::span<const Primitive> primitives)>;

  LeafItems() = default;
  // Static primitives only. They are referred to, not copied: they must outlive this object and
  // stay where they are (hits point into them).
  explicit LeafItems(std::span<const Primitive> primitives);
  // The primitives and instances of geometry (which must outlive this object). buildPrototype is
  // called once per prototype that has an instance and at least one primitive.
  LeafItems(const SceneGeometry& geometry, const PrototypeBuilder& buildPrototype);

  uint32_t size() const { return uint32_t(nPrimitives_ + instances_.size()); }
  bool empty() const { return size() == 0; }
  // World bound of item i (of an animated instance: over the whole shutter interval), padded by
  // a few ulps so that every hit its intersection can report lies inside (ray_query.h).
  Bounds3f bound(uint32_t i) const;

  // The item's closest hit in (0, ray.tMax): shrinks ray.tMax and fills *isect on a hit.
  bool intersect(uint32_t i, const Ray& ray, SurfaceInteraction* isect) const {
    if (i < nPrimitives_) {
      const Primitive& p = primitives_[i];
      Float t;
      if (!p.shape || !p.shape->intersect(ray, &t, isect)) return false;
      ray.tMax = t;
      isect->primitive = &p;
      return true;
    }
    return intersectInstance(instances_[i - nPrimitives_], ray, isect);
  }
  bool intersectP(uint32_t i, const Ray& ray) const {
    if (i < nPrimitives_) return primitives_[i].shape && primitives_[i].shape->intersectP(ray);
    return intersectInstanceP(instances_[i - nPrimitives_], ray);
  }

  long primitiveCount() const { return long(nPrimitives_); }
  long instanceCount() const { return long(instances_.size()); }
  long prototypeCount() const { return long(prototypes_.size()); }
  // Bytes held here, the prototypes' sub-aggregates included (their stats' "bytes").
  long bytes() const;

 private:
  struct InstanceItem {
    const Aggregate* prototype;
    const AnimatedTransform* instanceToWorld;  // points into the SceneGeometry
    Transform worldToInstance;                 // for static instances
    Bounds3f worldBound;
  };
  bool intersectInstance(const InstanceItem& inst, const Ray& ray, SurfaceInteraction* isect) const;
  bool intersectInstanceP(const InstanceItem& inst, const Ray& ray) const;

  // Items [0, nPrimitives_) are the primitives (contiguous, not copied), then the instances. A
  // primitive without a shape has an empty bound and is never hit.
  const Primitive* primitives_ = nullptr;
  uint32_t nPrimitives_ = 0;
  std::vector<InstanceItem> instances_;
  std::vector<std::unique_ptr<Aggregate>> prototypes_;
};

}  // namespace candela
