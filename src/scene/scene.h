// What integrators render: the aggregate and the lights. Everything it points to is owned by the
// RenderJob the factories built.
#pragma once

#include <vector>

#include "accel/aggregate.h"
#include "lights/light.h"
#include "media/medium.h"

namespace candela {

// Per-thread counters, summed by the renderer at the end.
struct RayStats {
  uint64_t cameraRays = 0;
  uint64_t intersectionRays = 0;  // closest-hit queries, camera rays included
  uint64_t shadowRays = 0;        // occlusion queries
  RayStats& operator+=(const RayStats& o) {
    cameraRays += o.cameraRays;
    intersectionRays += o.intersectionRays;
    shadowRays += o.shadowRays;
    return *this;
  }
};

// pbrt-v3's named media as the scene uses them (MakeNamedMedium / MediumInterface); empty in a
// scene without them. Surfaces carry theirs on their Primitive.
struct SceneMedia {
  bool present = false;            // some shape, light or the camera names a medium
  const Medium* camera = nullptr;  // the medium camera rays start in (null: vacuum)
  struct LightMedium {
    const Light* light;
    const Medium* medium;
  };
  std::vector<LightMedium> lights;  // lights (not area lights) that sit in a medium
};

class Scene {
 public:
  // volume: the medium filling the scene (pbrt-v2's Volume regions, aggregated), null for none.
  Scene(const Aggregate* aggregate, std::vector<const Light*> lights,
        const Medium* volume = nullptr)
      : aggregate_(aggregate), lights_(std::move(lights)), volume_(volume) {}
  bool intersect(const Ray& ray, SurfaceInteraction* isect, RayStats& stats) const {
    ++stats.intersectionRays;
    return aggregate_->intersect(ray, isect);
  }
  // intersect for each of rays, traced as a batch (Aggregate::intersectCoherent).
  void intersectCoherent(std::span<const Ray> rays, SurfaceInteraction* isects, bool* hits,
                         RayStats& stats) const {
    stats.intersectionRays += rays.size();
    aggregate_->intersectCoherent(rays, isects, hits);
  }
  // Whether anything lies along the ray within its tMax (counted as a shadow ray).
  bool intersectP(const Ray& ray, RayStats& stats) const {
    ++stats.shadowRays;
    return aggregate_->intersectP(ray);
  }
  bool unoccluded(const VisibilityTester& vis, RayStats& stats) const {
    ++stats.shadowRays;
    return vis.unoccluded(*aggregate_);
  }
  const std::vector<const Light*>& lights() const { return lights_; }
  const Aggregate& aggregate() const { return *aggregate_; }
  // The geometry's bounds, grown to hold the volume's (pbrt 2e §1.3.1: lights at infinity place
  // their shadow-ray ends beyond both); an unbounded volume does not grow it.
  Bounds3f worldBound() const {
    Bounds3f b = aggregate_->worldBound();
    if (volume_) {
      Bounds3f v = volume_->worldBound();
      Vector3f d = v.diagonal();
      if (!v.empty() && d.x < kInfinity && d.y < kInfinity && d.z < kInfinity) b = unionOf(b, v);
    }
    return b;
  }
  // The medium that fills the scene (pbrt-v2 `Volume` regions); null when there is none.
  const Medium* volume() const { return volume_; }
  // pbrt-v3's named media (see SceneMedia); set once by the build.
  const SceneMedia& media() const { return media_; }
  void setMedia(SceneMedia media) { media_ = std::move(media); }
  // Whether the scene's textures read camera rays' differentials (they filter by the footprint
  // they give): the build says false for a scene without textures, whose camera rays are then
  // made without them (integrators may still ask for them). True unless set.
  bool needsRayDifferentials() const { return needsRayDifferentials_; }
  void setNeedsRayDifferentials(bool needs) { needsRayDifferentials_ = needs; }

 private:
  const Aggregate* aggregate_;
  std::vector<const Light*> lights_;
  const Medium* volume_ = nullptr;
  SceneMedia media_;
  bool needsRayDifferentials_ = true;
};

}  // namespace candela
