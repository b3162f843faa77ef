// The ceiling of the render benchmark: the rays a path tracer traces through a scene (camera rays,
// a diffuse bounce and one shadow ray toward a light at every vertex, up to the integrator's
// depth), traced by Embree alone, with no shading, no interaction and no sampler. What is timed
// is only the Embree queries (each thread's CPU clock around its batches of rtcIntersect1 or
// rtcOccluded1 calls); the rays themselves are made between the batches, untimed, with candela's
// camera, light sampling and ray spawning and given to Embree as the aggregate gives them, so they
// are the rays candela would trace.
//
// The Embree scene is built as candela builds it (the same device configuration, robust
// traversal, medium build quality), from the scene's triangle meshes and whole spheres (Embree's
// native spheres: what Embree alone would use; candela runs its own double-precision quadric
// test as user geometry). Other shapes and instances are refused.
#pragma once

#include <embree3/rtcore.h>

#include <cstdint>
#include <vector>

#include "accel/scene_geometry.h"
#include "cameras/camera.h"
#include "lights/light.h"

namespace candela {

class EmbreeDevice;

namespace bench {

struct CeilingOptions {
  Bounds2i pixels;    // the film's pixel bounds
  int spp = 1;        // samples per pixel
  int maxDepth = 5;   // vertices per path, as the path integrator's maxdepth
  int threads = 1;    // worker threads (tiles are scheduled one at a time)
  int tileSize = 16;  // pixels per tile side, as the renderer's default
  uint64_t seed = 1;  // the untimed random choices (lens, time, bounce, light point)
  // Each wavefront of a tile as one stream query (rtcIntersect1M / rtcOccluded1M, camera rays
  // marked coherent) instead of one rtcIntersect1 / rtcOccluded1 call per ray: what gathering a
  // tile's secondary rays would buy a renderer.
  bool streams = false;
};

// Rays of one kind and the CPU seconds Embree spent on them (summed over threads).
struct RayKind {
  long rays = 0;
  double cpuSeconds = 0;
  // Rays per CPU second: the rate of one busy thread.
  double perCpuSecond() const { return cpuSeconds > 0 ? double(rays) / cpuSeconds : 0; }
};

struct CeilingResult {
  RayKind camera, bounce, shadow;
  double wallSeconds = 0;  // the whole run, ray making included
  // CPU seconds (summed over threads) spent between the queries: the camera rays, light points,
  // cosine-distributed bounces and spawning, with no BSDF, no MIS weight, no hit interaction and
  // no film. A scalar renderer that did only this work between the same queries would trace at
  // cpuSeconds() / (cpuSeconds() + makingSeconds) of the ceiling's rate.
  double makingSeconds = 0;
  long rays() const { return camera.rays + bounce.rays + shadow.rays; }
  double cpuSeconds() const { return camera.cpuSeconds + bounce.cpuSeconds + shadow.cpuSeconds; }
};

class EmbreeCeiling {
 public:
  // Throws std::runtime_error naming a shape it cannot give Embree (anything but triangles and
  // whole spheres under a similarity transform) or when the scene has instances.
  EmbreeCeiling(const EmbreeDevice& device, const SceneGeometry& geometry);
  ~EmbreeCeiling();
  EmbreeCeiling(const EmbreeCeiling&) = delete;
  EmbreeCeiling& operator=(const EmbreeCeiling&) = delete;

  // Traces the paths of every pixel sample. lights: the scene's (shadow rays go to a point
  // sampled on one chosen uniformly; none: no shadow rays).
  CeilingResult run(const Camera& camera, const std::vector<const Light*>& lights,
                    const CeilingOptions& options) const;

 private:
  RTCScene scene_ = nullptr;
};

}  // namespace bench
}  // namespace candela
