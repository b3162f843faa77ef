#include "transport/light_sampling.h"

#include "accel/primitive.h"
#include "core/sampling.h"
#include "transport/volume_transmittance.h"

namespace candela {

Spectrum ScatteringMixture::sample(const BSDF& bsdf, const Vector3f& wo, Float uComponent,
                                   const Point2f& u, Float uMix, Vector3f* wi, Float* pdf,
                                   BxDFType* type) const {
  // Either branch evaluates the BSDF as the light strategy does.
  bool sampled = true;
  if (uMix < bsdfShare) {
    bsdf.sampleF(wo, wi, uComponent, u, pdf, kAllBxDF, type);
    sampled = *pdf > 0;
  } else {
    Float guidePdf;
    *wi = guide->sample(u, &guidePdf);
  }
  *type = BxDFType(kDiffuse);
  *pdf = sampled ? this->pdf(bsdf, wo, *wi, kAllBxDF) : 0;
  return sampled ? bsdf.f(wo, *wi) : Spectrum(0);
}

ScatteringMixture guidedMixture(const GuidingField* field, const BSDF& bsdf, const Point3f& p) {
  const int nonSpecular = bsdf.numComponents(kAllBxDF & ~kSpecular);
  if (field && nonSpecular > 0 && bsdf.numComponents() == nonSpecular)
    if (const DirectionalQuadtree& d = field->at(p); d.trained()) return {&d, kGuidedBsdfShare};
  return {};
}

namespace {

// The light strategy: one sample of `light`, chosen with probability 1 / choices (among
// `choices` lights with equal probability, or by a LightSampler; the strategy's density is the
// light's over choices), weighted by the power heuristic against
// the BSDF's density of the direction over the components in bsdfFlags. volume: set when the
// caller can attenuate by the scene's volume (pbrt-v2 Volume regions).
Spectrum sampleLightStrategy(const SurfaceInteraction& it, const BSDF& bsdf, const Light& light,
                             const Point2f& uLight, Float choices, int bsdfFlags,
                             const Scene& scene, RayStats& stats, IntegratorContext* volume,
                             const ScatteringMixture* mixture = nullptr) {
  Vector3f wi;
  Float lightPdf = 0;
  // Its ends not zeroed: every light's sampleLi writes both when it returns a sample (a positive
  // density and some radiance), the only case in which they are read below.
  VisibilityTester vis{Interaction(kUninitialized), Interaction(kUninitialized)};
  Spectrum li = light.sampleLi(it, uLight, &wi, &lightPdf, &vis);
  if (!(lightPdf > 0) || li.isBlack()) return Spectrum(0);
  Spectrum f = bsdf.f(it.wo, wi, kAllBxDF & ~kSpecular) * absDot(wi, bsdf.shadingNormal());
  if (f.isBlack()) return Spectrum(0);
  // The estimate before the shadow ray, which only decides whether it counts: its divisions then
  // overlap the ray's setup and traversal rather than following them.
  Float pdf = lightPdf / choices;
  Spectrum estimate = light.isDelta()
                          ? f * li / pdf
                          : f * li *
                                (powerHeuristic(1, pdf, 1,
                                                mixture ? mixture->pdf(bsdf, it.wo, wi, bsdfFlags)
                                                        : bsdf.pdf(it.wo, wi, bsdfFlags)) /
                                 pdf);
  if (!scene.unoccluded(vis, stats)) return Spectrum(0);
  if (volume) estimate *= volumeTransmittance(vis, scene, *volume);
  return estimate;
}

// One sample of each strategy for `light` (pbrt 2e §15.1).
Spectrum estimateDirectThrough(const SurfaceInteraction& it, const BSDF& bsdf, const Light& light,
                               const Point2f& uLight, const Point2f& uScattering, Float uComponent,
                               const Scene& scene, RayStats& stats, IntegratorContext* volume) {
  const int nonSpecular = kAllBxDF & ~kSpecular;
  Spectrum ld = sampleLightStrategy(it, bsdf, light, uLight, 1, nonSpecular, scene, stats, volume);
  // BSDF sampling, for lights that a direction can hit.
  if (!light.isDelta()) {
    Vector3f wi;
    Float scatteringPdf = 0;
    BxDFType sampledType;
    Spectrum f = bsdf.sampleF(it.wo, &wi, uComponent, uScattering, &scatteringPdf, nonSpecular,
                              &sampledType);
    f *= absDot(wi, bsdf.shadingNormal());
    if (!f.isBlack() && scatteringPdf > 0) {
      Float lightPdf = light.pdfLi(it, wi);
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
  Float uChoice = ctx.get1D();
  Point2f uLight = ctx.get2D();
  return sampleOneLightAgainstBSDF(it, bsdf, scene, ctx, uChoice, uLight);
}

Spectrum sampleOneLightAgainstBSDF(const SurfaceInteraction& it, const BSDF& bsdf,
                                   const Scene& scene, IntegratorContext& ctx, Float uChoice,
                                   const Point2f& uLight, const ScatteringMixture* mixture) {
  int nLights = int(scene.lights().size());
  if (nLights == 0) return Spectrum(0);
  const Light& light = *scene.lights()[std::min(int(uChoice * nLights), nLights - 1)];
  // The density of a direction under the light strategy includes the choice of the light.
  return sampleLightStrategy(it, bsdf, light, uLight, Float(nLights), kAllBxDF, scene, ctx.stats,
                             &ctx, mixture);
}

Spectrum sampleLightAgainstBSDF(const SurfaceInteraction& it, const BSDF& bsdf, const Light& light,
                                Float choicePdf, const Scene& scene, IntegratorContext& ctx,
                                const Point2f& uLight, const ScatteringMixture* mixture) {
  if (!(choicePdf > 0)) return Spectrum(0);
  return sampleLightStrategy(it, bsdf, light, uLight, 1 / choicePdf, kAllBxDF, scene, ctx.stats,
                             &ctx, mixture);
}

}  // namespace candela
