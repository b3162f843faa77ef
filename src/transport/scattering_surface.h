// Passing through surfaces that do not scatter. A shape without a material (an interface between
// media, pbrt-v3's "interface" material) changes nothing of a ray that meets it: the ray goes on
// from it unchanged (continueThrough, specular_differentials.h), as pbrt-v4's SkipIntersection.
#pragma once

#include "accel/primitive.h"
#include "scene/scene.h"
#include "transport/specular_differentials.h"

namespace candela {

// The closest surface along *ray that has a material, passing straight through those that have
// none; false when the ray escapes. *ray is left as the ray continued to that hit, so that a
// caller that goes on from the hit, or from the escaped ray, sees what a path through the
// interfaces would. *isect must be a fresh record. atInterface(const SurfaceInteraction&) sees
// each surface passed through, in order, before the ray goes on from it (to count its emission,
// or that the ray met anything at all).
//
// The walks that stop at an interface, or change something there, walk themselves: path and
// volpath count an interface crossing against nothing but stop at their depth limit on it, as
// pbrt-v3 does (so a path of maxdepth bounces does not see past it), and volpath changes medium.
template <typename AtInterface>
bool intersectScattering(const Scene& scene, RayDifferential* ray, SurfaceInteraction* isect,
                         RayStats& stats, AtInterface&& atInterface) {
  for (;;) {
    const Float tMax = ray->tMax;  // intersect shortens ray->tMax to the hit
    if (!scene.intersect(*ray, isect, stats)) return false;
    if (isect->primitive->material) return true;
    atInterface(static_cast<const SurfaceInteraction&>(*isect));
    *ray = continueThrough(*isect, *ray, tMax);
    // The next surface starts from a fresh record, as each surface did in the walks' own loops
    // (the caller's is fresh for the first).
    *isect = SurfaceInteraction();
  }
}

// The same for a ray the caller may not change but for its tMax, as Scene::intersect takes one:
// ray.tMax is shortened to the first surface met, interface or not, as intersect would (what
// transmittance along the ray then covers), and *continued is the ray past the interfaces.
template <typename AtInterface>
bool intersectScattering(const Scene& scene, const RayDifferential& ray, RayDifferential* continued,
                         SurfaceInteraction* isect, RayStats& stats, AtInterface&& atInterface) {
  *continued = ray;
  bool crossed = false;
  Float firstHit = 0;
  bool hit = intersectScattering(scene, continued, isect, stats, [&](const SurfaceInteraction& at) {
    if (!crossed) firstHit = continued->tMax;
    crossed = true;
    atInterface(at);
  });
  ray.tMax = crossed ? firstHit : continued->tMax;
  return hit;
}

inline bool intersectScattering(const Scene& scene, RayDifferential* ray, SurfaceInteraction* isect,
                                RayStats& stats) {
  return intersectScattering(scene, ray, isect, stats, [](const SurfaceInteraction&) {});
}

}  // namespace candela
