#include "transport/final_gather.h"

#include <algorithm>

#include "accel/primitive.h"
#include "core/sampling.h"
#include "materials/material.h"
#include "transport/scattering_surface.h"
#include "transport/specular_differentials.h"

namespace candela {

namespace {

constexpr int kNonSpecular = kAllBxDF & ~kSpecular;

}  // namespace

Vector3f PhotonConeDirections::sample(Float u, const Point2f& u2, int* cone) const {
  int n = int(axes_.size());
  int i = std::min(int(u * Float(n)), n - 1);
  *cone = i;
  Vector3f local = sampleUniformCone(u2, cosAngle_);
  Vector3f s, t;
  coordinateSystem(axes_[i], &s, &t);
  return normalize(s * local.x + t * local.y + axes_[i] * local.z);
}

Float PhotonConeDirections::pdf(const Vector3f& w, int knownCone) const {
  if (axes_.empty()) return 0;
  int inside = 0;
  for (int i = 0; i < int(axes_.size()); ++i)
    if (i == knownCone || dot(axes_[i], w) >= cosAngle_) ++inside;
  return uniformConePdf(cosAngle_) * Float(inside) / Float(axes_.size());
}

std::span<const Vector3f> nearbyPhotonDirections(const PhotonMap& indirect, const Point3f& p,
                                                 int count, MemoryArena& arena) {
  count = int(std::min<size_t>(size_t(std::max(count, 0)), indirect.size()));
  if (count == 0) return {};
  // The k nearest at any distance: pbrt-v2 doubles its search radius until it holds k photons,
  // which finds the same ones (and never ends on a map with fewer than k).
  auto* near = static_cast<NearPhoton*>(arena.alloc(sizeof(NearPhoton) * size_t(count)));
  int found = indirect.nearest(p, kInfinity, std::span<NearPhoton>(near, size_t(count)));
  // The directions alone, contiguous, since every gather ray tests them all.
  auto* dirs = static_cast<Vector3f*>(arena.alloc(sizeof(Vector3f) * size_t(found)));
  for (int i = 0; i < found; ++i) dirs[i] = near[i].photon->wi;
  return {dirs, size_t(found)};
}

Spectrum gatherRayRadiance(const RayDifferential& start, const RadiancePhotonMap& radiance,
                           const Scene& scene, IntegratorContext& ctx, int maxSpecularDepth) {
  RayDifferential ray(start);
  Spectrum beta(1);
  for (int bounces = 0;;) {
    SurfaceInteraction isect;
    if (!intersectScattering(scene, &ray, &isect, ctx.stats)) return Spectrum(0);
    const Primitive& prim = *isect.primitive;
    const BSDF* bsdf = prim.material->getBSDF(isect, ctx.arena);
    if (bsdf->numComponents(kNonSpecular) > 0) {
      const RadiancePhoton* rp = radiance.nearest(isect.p, faceForward(isect.n, isect.wo));
      return rp ? beta * rp->Lo : Spectrum(0);
    }
    if (bounces++ >= maxSpecularDepth) return Spectrum(0);
    Vector3f wi;
    Float pdf;
    Spectrum f = bsdf->sampleF(isect.wo, &wi, ctx.sampler.get1D(), ctx.sampler.get2D(), &pdf);
    if (f.isBlack() || pdf == 0) return Spectrum(0);
    beta *= f * (absDot(wi, bsdf->shadingNormal()) / pdf);
    ray = RayDifferential(isect.spawnRay(wi));
  }
}

Spectrum finalGather(const SurfaceInteraction& it, const BSDF& bsdf,
                     const PhotonConeDirections& cones, const RadiancePhotonMap& radiance,
                     const Scene& scene, IntegratorContext& ctx, const FinalGatherSettings& s) {
  const int n = s.samplesPerStrategy;
  const Normal3f ns = bsdf.shadingNormal();
  Spectrum fromBsdf(0), fromPhotons(0);
  for (int i = 0; i < n; ++i) {
    Vector3f wi;
    Float pdf;
    Float uc = ctx.sampler.get1D();
    Point2f u2 = ctx.sampler.get2D();
    Spectrum f = bsdf.sampleF(it.wo, &wi, uc, u2, &pdf, kNonSpecular);
    if (f.isBlack() || pdf == 0) continue;
    Spectrum li = gatherRayRadiance(RayDifferential(it.spawnRay(wi)), radiance, scene, ctx,
                                    s.maxSpecularDepth);
    if (li.isBlack()) continue;
    Float w = powerHeuristic(n, pdf, n, cones.pdf(wi));
    fromBsdf += f * li * (absDot(wi, ns) * w / pdf);
  }
  if (!cones.empty()) {
    for (int i = 0; i < n; ++i) {
      int cone;
      Float uc = ctx.sampler.get1D();
      Point2f u2 = ctx.sampler.get2D();
      Vector3f wi = cones.sample(uc, u2, &cone);
      Spectrum f = bsdf.f(it.wo, wi, kNonSpecular);
      if (f.isBlack()) continue;
      Spectrum li = gatherRayRadiance(RayDifferential(it.spawnRay(wi)), radiance, scene, ctx,
                                      s.maxSpecularDepth);
      if (li.isBlack()) continue;
      Float pdf = cones.pdf(wi, cone);
      Float w = powerHeuristic(n, pdf, n, bsdf.pdf(it.wo, wi, kNonSpecular));
      fromPhotons += f * li * (absDot(wi, ns) * w / pdf);
    }
  }
  return (fromBsdf + fromPhotons) / Float(n);
}

}  // namespace candela
