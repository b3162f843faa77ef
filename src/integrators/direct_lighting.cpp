#include "integrators/direct_lighting.h"

#include "accel/primitive.h"
#include "integrators/light_sampling.h"
#include "materials/material.h"

namespace candela {

Spectrum DirectLightingIntegrator::Li(const RayDifferential& ray, const Scene& scene,
                                      IntegratorContext& ctx, Float* alpha) const {
  return trace(ray, scene, ctx, 0, alpha);
}

Spectrum DirectLightingIntegrator::trace(const RayDifferential& ray, const Scene& scene,
                                         IntegratorContext& ctx, int depth, Float* alpha) const {
  SurfaceInteraction isect;
  Spectrum l(0);
  if (!scene.intersect(ray, &isect, ctx.stats)) {
    *alpha = 0;
    for (const Light* light : scene.lights()) l += light->Le(ray);
    return l;
  }
  *alpha = 1;
  const Primitive& prim = *isect.primitive;
  if (prim.areaLight) l += prim.areaLight->L(isect, isect.wo);
  if (!prim.material) {
    // An interface without scattering: continue straight through.
    Float a;
    return l + trace(RayDifferential(isect.spawnRay(ray.d)), scene, ctx, depth, &a);
  }
  isect.computeDifferentials(ray);
  const BSDF* bsdf = prim.material->getBSDF(isect, ctx.arena);
  if (strategy_ == Strategy::All)
    l += uniformSampleAllLights(isect, *bsdf, scene, ctx);
  else
    l += uniformSampleOneLight(isect, *bsdf, scene, ctx);

  if (depth + 1 < maxDepth_) {
    // Perfect specular reflection and transmission, followed recursively.
    for (int flags : {kReflection | kSpecular, kTransmission | kSpecular}) {
      Vector3f wi;
      Float pdf;
      Spectrum f =
          bsdf->sampleF(isect.wo, &wi, ctx.sampler.get1D(), ctx.sampler.get2D(), &pdf, flags);
      Float cosTerm = absDot(wi, isect.shading.n);
      if (pdf > 0 && !f.isBlack() && cosTerm != 0) {
        Float a;
        RayDifferential next(isect.spawnRay(wi));
        l += f * trace(next, scene, ctx, depth + 1, &a) * (cosTerm / pdf);
      }
    }
  }
  return l;
}

}  // namespace candela
