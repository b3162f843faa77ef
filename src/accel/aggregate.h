// Ray queries over all primitives of a scene. Integrators see only this interface; Embree and the
// book's kd-tree and grid implement it.
#pragma once

#include <map>
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
  virtual AggregateStats stats() const = 0;
};

}  // namespace candela
