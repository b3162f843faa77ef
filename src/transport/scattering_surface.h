// Passing through surfaces that do not scatter. A shape without a material (an interface between
// media, pbrt-v3's "interface" material) changes nothing of a ray that meets it: the ray goes on
// from it unchanged (continueThrough, specular_differentials.h), as pbrt-v4's SkipIntersection.
#pragma once

#include "scene/scene.h"

namespace candela {

// The closest surface along *ray that has a material, passing straight through those that have
// none; false when the ray escapes. *ray is left as the ray continued to that hit, so that a
// caller that goes on from the hit, or from the escaped ray, sees what a path through the
// interfaces would. *isect must be a fresh record. For walks that do nothing at an interface;
// those that do something there (count its emission, change medium, stop at a depth) walk
// themselves.
bool intersectScattering(const Scene& scene, RayDifferential* ray, SurfaceInteraction* isect,
                         RayStats& stats);

}  // namespace candela
