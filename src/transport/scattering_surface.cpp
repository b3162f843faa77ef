#include "transport/scattering_surface.h"

#include "accel/primitive.h"
#include "transport/specular_differentials.h"

namespace candela {

bool intersectScattering(const Scene& scene, RayDifferential* ray, SurfaceInteraction* isect,
                         RayStats& stats) {
  for (;;) {
    const Float tMax = ray->tMax;  // intersect shortens ray->tMax to the hit
    if (!scene.intersect(*ray, isect, stats)) return false;
    if (isect->primitive->material) return true;
    *ray = continueThrough(*isect, *ray, tMax);
    // The next surface starts from a fresh record, as each surface did in the walks' own loops
    // (the caller's is fresh for the first).
    *isect = SurfaceInteraction();
  }
}

}  // namespace candela
