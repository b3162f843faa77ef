#include "integrators/specular_recursion.h"

#include "accel/primitive.h"
#include "materials/material.h"
#include "transport/scattering_surface.h"
#include "transport/specular_differentials.h"
#include "transport/volume_transmittance.h"

namespace candela {

Spectrum SpecularRecursionIntegrator::Li(const RayDifferential& ray, const Scene& scene,
                                         IntegratorContext& ctx, Float* alpha) const {
  return trace(ray, scene, ctx, 0, alpha, nullptr);
}

Spectrum SpecularRecursionIntegrator::traceWith(const RayDifferential& ray, const Scene& scene,
                                                IntegratorContext& ctx,
                                                const SurfaceTerm& term) const {
  Float alpha;
  return trace(ray, scene, ctx, 0, &alpha, &term);
}

Spectrum SpecularRecursionIntegrator::trace(const RayDifferential& ray, const Scene& scene,
                                            IntegratorContext& ctx, int depth, Float* alpha,
                                            const SurfaceTerm* term) const {
  SurfaceInteraction isect;
  RayDifferential r;
  // An interface passed on the way is seen (its emission) but does not scatter: the ray goes on
  // at the same depth.
  Spectrum interfaces(0);
  bool crossed = false;
  bool hit =
      intersectScattering(scene, ray, &r, &isect, ctx.stats, [&](const SurfaceInteraction& at) {
        crossed = true;
        if (at.primitive->areaLight) interfaces += at.primitive->areaLight->L(at, at.wo);
      });
  *alpha = hit || crossed ? 1 : 0;
  Spectrum l(0);
  if (!hit) {
    for (const Light* light : scene.lights()) l += light->Le(r);
    return crossed ? interfaces + l : l;
  }
  const Primitive& prim = *isect.primitive;
  if (prim.areaLight) l += prim.areaLight->L(isect, isect.wo);
  isect.computeDifferentials(r);
  const BSDF* bsdf = prim.material->getBSDF(isect, ctx.arena);
  l += term ? (*term)(isect, *bsdf, ctx) : directLight(isect, *bsdf, scene, ctx);

  if (depth + 1 < maxDepth_)
    l += specularlyScattered(isect, *bsdf, r, ctx.sampler, [&](const RayDifferential& next) {
      Float a;
      Spectrum li = trace(next, scene, ctx, depth + 1, &a, term);  // next.tMax is now the hit's
      return li * volumeTransmittance(next, scene, ctx);
    });
  return crossed ? interfaces + l : l;
}

}  // namespace candela
