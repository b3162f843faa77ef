// Ray queries over all primitives of a scene. Integrators see only this interface; Embree and the
// book's kd-tree and grid implement it.
#pragma once

#include <map>
#include <span>
#include <string>

#include "accel/primitive.h"

namespace candela {

struct AggregateStats {
  std::string name;                    // "embree", "kdtree", ...
  std::map<std::string, long> counts;  // e.g. "embree triangle meshes", "embree user geometries"
};

class Aggregate {
 public:
  virtual ~Aggregate() = default;
  virtual Bounds3f worldBound() const = 0;
  // The closest hit in (0, ray.tMax); on a hit, ray.tMax is set to its distance and *isect filled
  // (isect->primitive set).
  virtual bool intersect(const Ray& ray, SurfaceInteraction* isect) const = 0;
  // Any hit in (0, ray.tMax).
  virtual bool intersectP(const Ray& ray) const = 0;
  // The closest hits of rays that start close together and point alike (a pixel's camera rays),
  // asked together so that the aggregate can trace them as a batch: each as intersect(rays[i],
  // &isects[i]) finds it, hits[i] its result. The hit is a function of the ray and of the rays
  // asked with it; it may differ from intersect's where two surfaces tie (a ray along an edge
  // shared by two triangles). This default asks intersect one ray at a time.
  virtual void intersectCoherent(std::span<const Ray> rays, SurfaceInteraction* isects,
                                 bool* hits) const {
    for (size_t i = 0; i < rays.size(); ++i) hits[i] = intersect(rays[i], &isects[i]);
  }
  // Whether intersectCoherent is faster than intersect one ray at a time (Embree's packets), so
  // that a renderer gains by gathering rays for it.
  virtual bool tracesCoherentRaysFaster() const { return false; }
  virtual AggregateStats stats() const = 0;
};

}  // namespace candela
