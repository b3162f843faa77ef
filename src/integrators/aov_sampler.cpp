#include "integrators/aov_sampler.h"

#include "accel/primitive.h"
#include "materials/material.h"

namespace candela {

namespace {
// The BSDF's directional albedo toward wo, from a fixed 4x4 stratified pattern: deterministic,
// and exact for Lambertian reflection; specular lobes are sampled exactly too.
Spectrum directionalAlbedo(const BSDF& bsdf, const Vector3f& wo) {
  const int n = 4;
  Spectrum sum(0);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      Point2f u((i + 0.5f) / n, (j + 0.5f) / n);
      Float uComponent = ((i * n + j) + 0.5f) / (n * n);
      Vector3f wi;
      Float pdf;
      Spectrum f = bsdf.sampleF(wo, &wi, uComponent, u, &pdf);
      if (pdf > 0 && !f.isBlack()) sum += f * (absDot(wi, bsdf.geometricNormal()) / pdf);
    }
  return sum / Float(n * n);
}
}  // namespace

AovSample sampleAovs(const Scene& scene, const RayDifferential& cameraRay, MemoryArena& arena,
                     RayStats& stats) {
  AovSample s;
  SurfaceInteraction isect;
  Ray ray = cameraRay;
  if (!scene.intersect(ray, &isect, stats)) return s;
  s.hit = true;
  s.depth = ray.tMax * ray.d.length();
  s.position = isect.p;
  s.normal = isect.shading.n;
  if (const Material* m = isect.primitive->material)
    s.albedo = directionalAlbedo(*m->getBSDF(isect, arena), isect.wo);
  return s;
}

}  // namespace candela
