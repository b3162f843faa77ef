#include "integrators/specular_recursion.h"

#include "accel/primitive.h"
#include "materials/material.h"
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
  Spectrum l(0);
  Float tMax = ray.tMax;  // intersect shortens ray.tMax to the hit
  if (!scene.intersect(ray, &isect, ctx.stats)) {
    *alpha = 0;
    for (const Light* light : scene.lights()) l += light->Le(ray);
    return l;
  }
  *alpha = 1;
  const Primitive& prim = *isect.primitive;
  if (prim.areaLight) l += prim.areaLight->L(isect, isect.wo);
  if (!prim.material) {
    // An interface without scattering: continue straight through, at the same depth.
    Float a;
    return l + trace(continueThrough(isect, ray, tMax), scene, ctx, depth, &a, term);
  }
  isect.computeDifferentials(ray);
  const BSDF* bsdf = prim.material->getBSDF(isect, ctx.arena);
  l += term ? (*term)(isect, *bsdf, ctx) : directLight(isect, *bsdf, scene, ctx);

  if (depth + 1 < maxDepth_)
    l += specularlyScattered(isect, *bsdf, ray, ctx.sampler, [&](const RayDifferential& next) {
      Float a;
      Spectrum li = trace(next, scene, ctx, depth + 1, &a, term);  // next.tMax is now the hit's
      return li * volumeTransmittance(next, scene, ctx);
    });
  return l;
}

}  // namespace candela
