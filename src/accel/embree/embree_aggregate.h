// The Aggregate on Embree (DESIGN.md, "Intersection is Embree's"). Runs of consecutive triangles
// of one mesh become one native Embree triangle geometry; every other shape (the quadrics) is a
// primitive of one Embree user geometry whose callbacks call the shape's own intersection.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "accel/aggregate.h"
#include "accel/embree/embree_device.h"

struct RTCSceneTy;  // Embree's RTCScene is RTCSceneTy*

namespace candela {

class EmbreeAggregate : public Aggregate {
 public:
  enum class BuildQuality { Medium, High };

  // Neither device nor primitives is copied: both must outlive the aggregate, and primitives
  // must stay where they are, since hits point into them. Throws EmbreeError when Embree fails.
  EmbreeAggregate(const EmbreeDevice& device, const std::vector<Primitive>& primitives,
                  BuildQuality quality = BuildQuality::Medium);
  ~EmbreeAggregate() override;
  EmbreeAggregate(const EmbreeAggregate&) = delete;
  EmbreeAggregate& operator=(const EmbreeAggregate&) = delete;

  Bounds3f worldBound() const override { return bounds_; }
  // Rays with NaN or infinite origin or direction components, a zero direction or a NaN tMax
  // miss. Hits at t = 0 are excluded (Embree's own test accepts t == tnear).
  bool intersect(const Ray& ray, SurfaceInteraction* isect) const override;
  bool intersectP(const Ray& ray) const override;
  // counts: "embree triangle geometries", "embree user geometries", "triangles",
  // "user primitives".
  AggregateStats stats() const override;

  // Per Embree geometry: which primitive each Embree primID is.
  struct Geometry {
    bool isUser = false;
    const Primitive* primitives = nullptr;  // the aggregate's primitives
    std::vector<uint32_t> primIndex;        // primID -> index into primitives
  };

 private:
  const EmbreeDevice* device_;
  RTCSceneTy* scene_ = nullptr;
  const Primitive* primitives_ = nullptr;
  std::vector<std::unique_ptr<Geometry>> geometries_;  // by geomID; stable for Embree's user ptr
  Bounds3f bounds_;
  long triangleGeometries_ = 0, userGeometries_ = 0, triangles_ = 0, userPrimitives_ = 0;
};

}  // namespace candela
