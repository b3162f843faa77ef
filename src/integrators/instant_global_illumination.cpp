#include "integrators/instant_global_illumination.h"

#include <bit>
#include <cmath>

#include "accel/primitive.h"
#include "core/rng.h"
#include "materials/material.h"
#include "transport/light_sampling.h"
#include "transport/scattering_surface.h"
#include "transport/specular_differentials.h"

namespace candela {

namespace {

// A VPL whose contribution falls below rrthreshold is kept with this probability (pbrt 2e
// §15.4) and, when kept, weighted by its inverse.
constexpr Float kFaintLightKeepProbability = 0.1f;

const int kNonSpecular = kAllBxDF & ~kSpecular;

}  // namespace

void InstantGlobalIlluminationIntegrator::preprocess(const Scene& scene,
                                                     const PreprocessOptions& options) {
  // --quick traces a quarter of the light paths (pbrt-v2's rule).
  int paths = options.quick ? std::max(1, params_.pathsPerSet / 4) : params_.pathsPerSet;
  VirtualPointLightOptions vplOptions{options.seed, options.shutterOpen, options.shutterClose};
  vpls_ = traceVirtualPointLights(scene, params_.nSets, paths, vplOptions);
}

std::string InstantGlobalIlluminationIntegrator::statsReport() const {
  return "Instant global illumination\n  virtual point lights  " + std::to_string(vpls_.count()) +
         "\n  virtual point light bytes  " + std::to_string(vpls_.memoryBytes()) + "\n";
}

Spectrum InstantGlobalIlluminationIntegrator::Li(const RayDifferential& ray, const Scene& scene,
                                                 IntegratorContext& ctx, Float* alpha) const {
  // One set per camera sample: its VPLs serve every vertex of this sample's tree of rays.
  int set = std::min(int(ctx.sampler.get1D() * Float(params_.nSets)), params_.nSets - 1);
  return trace(ray, scene, ctx, set, 0, true, alpha);
}

Spectrum InstantGlobalIlluminationIntegrator::trace(const RayDifferential& ray, const Scene& scene,
                                                    IntegratorContext& ctx, int set, int depth,
                                                    bool withEmission, Float* alpha) const {
  SurfaceInteraction isect;
  RayDifferential r;
  // An interface passed on the way is seen (its emission) but does not scatter.
  Spectrum interfaces(0);
  bool crossed = false;
  bool hit =
      intersectScattering(scene, ray, &r, &isect, ctx.stats, [&](const SurfaceInteraction& at) {
        crossed = true;
        if (withEmission && at.primitive->areaLight)
          interfaces += at.primitive->areaLight->L(at, at.wo);
      });
  *alpha = hit || crossed ? 1 : 0;
  Spectrum l(0);
  if (!hit) {
    if (withEmission)
      for (const Light* light : scene.lights()) l += light->Le(r);
    return crossed ? interfaces + l : l;
  }
  const Primitive& prim = *isect.primitive;
  if (withEmission && prim.areaLight) l += prim.areaLight->L(isect, isect.wo);
  l += scatter(isect, r, scene, ctx, set, depth);
  return crossed ? interfaces + l : l;
}

Spectrum InstantGlobalIlluminationIntegrator::scatter(SurfaceInteraction& isect,
                                                      const RayDifferential& ray,
                                                      const Scene& scene, IntegratorContext& ctx,
                                                      int set, int depth) const {
  const Primitive& prim = *isect.primitive;
  isect.computeDifferentials(ray);
  const BSDF* bsdf = prim.material->getBSDF(isect, ctx.arena);
  Spectrum l = uniformSampleAllLights(isect, *bsdf, scene, ctx);
  l += gatherVirtualLights(isect, *bsdf, scene, ctx, set);
  if (depth < params_.maxDepth) l += compensateBound(isect, *bsdf, scene, ctx, set, depth);

  // What the mirror shows is seen, emission included, whatever ray arrived here.
  if (depth + 1 < params_.maxDepth)
    l += specularlyScattered(isect, *bsdf, ray, ctx.sampler, [&](const RayDifferential& next) {
      Float a;
      return trace(next, scene, ctx, set, depth + 1, true, &a);
    });
  return l;
}

Spectrum InstantGlobalIlluminationIntegrator::gatherVirtualLights(const SurfaceInteraction& isect,
                                                                  const BSDF& bsdf,
                                                                  const Scene& scene,
                                                                  IntegratorContext& ctx,
                                                                  int set) const {
  // The roulette below draws from a generator seeded by this vertex's sampler values, so the
  // number of VPLs does not change how many dimensions a sample uses.
  Point2f u = ctx.sampler.get2D();
  if (size_t(set) >= vpls_.sets.size()) return Spectrum(0);  // not preprocessed
  const std::vector<VirtualPointLight>& vpls = vpls_.sets[size_t(set)];
  if (vpls.empty() || bsdf.numComponents(kNonSpecular) == 0) return Spectrum(0);
  RNG rng(hashValues({std::bit_cast<uint32_t>(u.x), std::bit_cast<uint32_t>(u.y)}));
  Normal3f ns = bsdf.shadingNormal();
  Float perPath = Float(1) / Float(vpls_.pathsPerSet);
  Spectrum l(0);
  for (const VirtualPointLight& vpl : vpls) {
    Vector3f toLight = vpl.at.p - isect.p;
    Float d2 = toLight.lengthSquared();
    if (d2 == 0) continue;
    Vector3f wi = toLight / std::sqrt(d2);
    Float cosLight = -dot(vpl.at.n, wi);  // the VPL lights only the side it was lit from
    if (cosLight <= 0) continue;
    Spectrum f = bsdf.f(isect.wo, wi);
    if (f.isBlack()) continue;
    // The bound on G keeps VPLs near the point from showing as bright spots (pbrt 2e §15.4).
    Float g = std::min(absDot(wi, ns) * cosLight / d2, params_.gLimit);
    Spectrum contribution = f * vpl.contribution * (g * perPath);
    if (contribution.y() < params_.rrThreshold) {
      if (!(rng.uniformFloat() < kFaintLightKeepProbability)) continue;
      contribution = contribution / kFaintLightKeepProbability;
    }
    if (scene.intersectP(isect.spawnRayTo(vpl.at), ctx.stats)) continue;
    l += contribution;
  }
  return l;
}

Spectrum InstantGlobalIlluminationIntegrator::compensateBound(const SurfaceInteraction& isect,
                                                              const BSDF& bsdf, const Scene& scene,
                                                              IntegratorContext& ctx, int set,
                                                              int depth) const {
  // Kollig and Keller's compensation (pbrt 2e §15.4): the part of the VPL integral the bound
  // removes, the integral over surfaces of f (G - glimit)^+ L dA, is written over directions as
  // the integral of f L |cos| (G - glimit)^+ / G dw and estimated with BSDF-sampled rays. G
  // exceeds glimit only closer than sqrt(|cos| / glimit), so the rays stop there. L is the light
  // the surface found reflects, computed by this integrator one level deeper.
  int n = depth == 0 ? params_.gatherSamples : 1;
  if (bsdf.numComponents(kNonSpecular) == 0) return Spectrum(0);
  Normal3f ns = bsdf.shadingNormal();
  Spectrum l(0);
  for (int k = 0; k < n; ++k) {
    Float uComponent = ctx.sampler.get1D();
    Point2f uDirection = ctx.sampler.get2D();
    Vector3f wi;
    Float pdf;
    Spectrum f = bsdf.sampleF(isect.wo, &wi, uComponent, uDirection, &pdf, kNonSpecular);
    if (f.isBlack() || pdf == 0) continue;
    Float cosHere = absDot(wi, ns);
    RayDifferential ray(isect.spawnRay(wi));
    ray.tMax = std::sqrt(cosHere / params_.gLimit);
    // Find the first surface that scatters, passing through those without a material.
    SurfaceInteraction hit;
    if (!intersectScattering(scene, &ray, &hit, ctx.stats)) continue;
    Float g = cosHere * absDot(wi, hit.n) / distanceSquared(isect.p, hit.p);
    if (!(g > params_.gLimit) || std::isinf(g)) continue;
    Spectrum li = scatter(hit, ray, scene, ctx, set, depth + 1);
    l += f * li * (cosHere * (g - params_.gLimit) / g / (Float(n) * pdf));
  }
  return l;
}

}  // namespace candela
