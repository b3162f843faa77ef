#include "integrators/path.h"

#include "accel/primitive.h"
#include "integrators/light_sampling.h"
#include "integrators/specular_differentials.h"
#include "integrators/volume_transmittance.h"
#include "materials/material.h"

namespace candela {

Spectrum PathIntegrator::Li(const RayDifferential& ray, const Scene& scene, IntegratorContext& ctx,
                            Float* alpha) const {
  Float hitDistance;
  return radiance(ray, scene, ctx, true, alpha, &hitDistance);
}

Spectrum PathIntegrator::scatteredLi(const RayDifferential& ray, const Scene& scene,
                                     IntegratorContext& ctx, Float* hitDistance) const {
  Float alpha;
  return radiance(ray, scene, ctx, false, &alpha, hitDistance);
}

Spectrum PathIntegrator::radiance(const RayDifferential& cameraRay, const Scene& scene,
                                  IntegratorContext& ctx, bool firstEmission, Float* alpha,
                                  Float* hitDistance) const {
  Spectrum l(0), beta(1);
  RayDifferential ray(cameraRay);
  bool specularBounce = false;
  *alpha = 0;
  for (int bounces = 0;; ++bounces) {
    SurfaceInteraction isect;
    Float tMax = ray.tMax;  // intersect shortens ray.tMax to the hit
    bool hit = scene.intersect(ray, &isect, ctx.stats);
    // A segment after a bounce crosses the scene's volume (the camera ray's: the renderer's).
    if (bounces > 0) beta *= volumeTransmittance(ray, scene, ctx);
    if (bounces == 0) {
      *alpha = hit ? 1 : 0;
      *hitDistance = hit ? ray.tMax : kInfinity;
    }
    // Emission is counted here only where next-event estimation could not have sampled it.
    if ((bounces == 0 && firstEmission) || (bounces > 0 && specularBounce)) {
      if (hit) {
        if (isect.primitive->areaLight) l += beta * isect.primitive->areaLight->L(isect, -ray.d);
      } else {
        for (const Light* light : scene.lights()) l += beta * light->Le(ray);
      }
    }
    if (!hit || bounces >= maxDepth_) break;
    const Primitive& prim = *isect.primitive;
    if (!prim.material) {
      ray = continueThrough(isect, ray, tMax);
      --bounces;
      continue;
    }
    if (bounces == 0) isect.computeDifferentials(ray);
    const BSDF* bsdf = prim.material->getBSDF(isect, ctx.arena);
    if (bsdf->numComponents(kAllBxDF & ~kSpecular) > 0)
      l += beta * uniformSampleOneLight(isect, *bsdf, scene, ctx);

    Vector3f wi;
    Float pdf;
    BxDFType sampledType;
    Spectrum f =
        bsdf->sampleF(isect.wo, &wi, ctx.get1D(), ctx.get2D(), &pdf, kAllBxDF, &sampledType);
    if (f.isBlack() || pdf == 0) break;
    beta *= f * (absDot(wi, bsdf->shadingNormal()) / pdf);
    specularBounce = (sampledType & kSpecular) != 0;
    ray = RayDifferential(isect.spawnRay(wi));

    // Russian roulette: continue with probability tied to the throughput (pbrt 2e §15.3 uses
    // min(0.5, y); the throughput's largest channel wastes less on coloured paths).
    if (bounces >= rrStartDepth_) {
      Float q = std::max(Float(0.05), 1 - beta.maxComponent());
      if (ctx.get1D() < q) break;
      beta /= 1 - q;
    }
    if (!beta.isFinite()) break;
  }
  return l;
}

}  // namespace candela
