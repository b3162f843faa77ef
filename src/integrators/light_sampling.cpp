#include "integrators/light_sampling.h"

#include "accel/primitive.h"
#include "core/sampling.h"
#include "integrators/volume_transmittance.h"

namespace candela {

namespace {

// volume: set when the caller can attenuate by the scene's volume (pbrt-v2 Volume regions).
Spectrum estimateDirectThrough(const SurfaceInteraction& it, const BSDF& bsdf, const Light& light,
                               const Point2f& uLight, const Point2f& uScattering, Float uComponent,
                               const Scene& scene, RayStats& stats, IntegratorContext* volume) {
  const int nonSpecular = kAllBxDF & ~kSpecular;
  Spectrum ld(0);
  // Light sampling.
  Vector3f wi;
  Float lightPdf = 0, scatteringPdf = 0;
  VisibilityTester vis;
  Spectrum li = light.sampleLi(it, uLight, &wi, &lightPdf, &vis);
  if (lightPdf > 0 && !li.isBlack()) {
    Spectrum f = bsdf.f(it.wo, wi, nonSpecular) * absDot(wi, bsdf.shadingNormal());
    if (!f.isBlack() && scene.unoccluded(vis, stats)) {
      if (volume) li *= volumeTransmittance(vis, scene, *volume);
      if (light.isDelta()) {
        ld += f * li / lightPdf;
      } else {
        scatteringPdf = bsdf.pdf(it.wo, wi, nonSpecular);
        ld += f * li * (powerHeuristic(1, lightPdf, 1, scatteringPdf) / lightPdf);
      }
    }
  }
  // BSDF sampling, for lights that a direction can hit.
  if (!light.isDelta()) {
    BxDFType sampledType;
    Spectrum f = bsdf.sampleF(it.wo, &wi, uComponent, uScattering, &scatteringPdf, nonSpecular,
                              &sampledType);
    f *= absDot(wi, bsdf.shadingNormal());
    if (!f.isBlack() && scatteringPdf > 0) {
      lightPdf = light.pdfLi(it, wi);
      if (lightPdf == 0) return ld;
      Float weight = powerHeuristic(1, scatteringPdf, 1, lightPdf);
      SurfaceInteraction lightIsect;
      RayDifferential ray(it.spawnRay(wi));
      Spectrum le(0);
      if (scene.intersect(ray, &lightIsect, stats)) {
        const AreaLight* area = lightIsect.primitive ? lightIsect.primitive->areaLight : nullptr;
        if (area == &light) le = area->L(lightIsect, -wi);
      } else {
        le = light.Le(ray);
      }
      if (volume && !le.isBlack()) le *= volumeTransmittance(ray, scene, *volume);
      if (!le.isBlack()) ld += f * le * (weight / scatteringPdf);
    }
  }
  return ld;
}

}  // namespace

Spectrum estimateDirect(const SurfaceInteraction& it, const BSDF& bsdf, const Light& light,
                        const Point2f& uLight, const Point2f& uScattering, Float uComponent,
                        const Scene& scene, RayStats& stats) {
  return estimateDirectThrough(it, bsdf, light, uLight, uScattering, uComponent, scene, stats,
                               nullptr);
}

Spectrum uniformSampleAllLights(const SurfaceInteraction& it, const BSDF& bsdf, const Scene& scene,
                                IntegratorContext& ctx) {
  Spectrum l(0);
  for (const Light* light : scene.lights()) {
    int n = light->nSamples();
    Spectrum ld(0);
    for (int k = 0; k < n; ++k) {
      Point2f uLight = ctx.get2D();
      Point2f uScattering = ctx.get2D();
      Float uComponent = ctx.get1D();
      ld += estimateDirectThrough(it, bsdf, *light, uLight, uScattering, uComponent, scene,
                                  ctx.stats, &ctx);
    }
    l += ld / Float(n);
  }
  return l;
}

Spectrum uniformSampleOneLight(const SurfaceInteraction& it, const BSDF& bsdf, const Scene& scene,
                               IntegratorContext& ctx) {
  int nLights = int(scene.lights().size());
  Float uChoice = ctx.get1D();
  Point2f uLight = ctx.get2D();
  Point2f uScattering = ctx.get2D();
  Float uComponent = ctx.get1D();
  if (nLights == 0) return Spectrum(0);
  int index = std::min(int(uChoice * nLights), nLights - 1);
  const Light& light = *scene.lights()[index];
  return estimateDirectThrough(it, bsdf, light, uLight, uScattering, uComponent, scene, ctx.stats,
                               &ctx) *
         Float(nLights);
}

Spectrum sampleOneLightAgainstBSDF(const SurfaceInteraction& it, const BSDF& bsdf,
                                   const Scene& scene, IntegratorContext& ctx) {
  int nLights = int(scene.lights().size());
  Float uChoice = ctx.get1D();
  Point2f uLight = ctx.get2D();
  if (nLights == 0) return Spectrum(0);
  const Light& light = *scene.lights()[std::min(int(uChoice * nLights), nLights - 1)];
  Vector3f wi;
  Float lightPdf = 0;
  VisibilityTester vis;
  Spectrum li = light.sampleLi(it, uLight, &wi, &lightPdf, &vis);
  if (lightPdf == 0 || li.isBlack()) return Spectrum(0);
  Spectrum f = bsdf.f(it.wo, wi, kAllBxDF & ~kSpecular) * absDot(wi, bsdf.shadingNormal());
  if (f.isBlack() || !scene.unoccluded(vis, ctx.stats)) return Spectrum(0);
  li *= volumeTransmittance(vis, scene, ctx);
  // The density of this direction under the light strategy includes the choice of the light.
  Float pdf = lightPdf / Float(nLights);
  if (light.isDelta()) return f * li / pdf;
  Float weight = powerHeuristic(1, pdf, 1, bsdf.pdf(it.wo, wi, kAllBxDF));
  return f * li * (weight / pdf);
}

}  // namespace candela
