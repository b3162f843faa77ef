#include "integrators/path.h"

#include <algorithm>
#include <string>

#include "accel/primitive.h"
#include "core/sampling.h"
#include "materials/material.h"
#include "transport/guide_recorder.h"
#include "transport/light_sampling.h"
#include "transport/specular_differentials.h"
#include "transport/volume_transmittance.h"

namespace candela {

void PathIntegrator::preprocess(const Scene& scene, const PreprocessOptions& options) {
  if (std::string notice = lightStrategyNotice(settings_.lightStrategy, scene.lights().size());
      !notice.empty() && options.warn)
    options.warn(notice);
  lightSampler_.reset();
  if (settings_.lightStrategy != LightSampleStrategy::Uniform)
    lightSampler_ = createLightSampler(settings_.lightStrategy, scene.lights(), scene.worldBound());
}

PixelSampleIntegrator::SampleLoop PathIntegrator::guidedSampleLoop(const RenderInputs& in,
                                                                   const Film& film) const {
  SampleLoop loop = sampleLoop(in, film);
  loop.firstHit = this;
  return loop;
}

Spectrum PathIntegrator::Li(const RayDifferential& ray, const Scene& scene, IntegratorContext& ctx,
                            Float* alpha) const {
  Float hitDistance;
  return radiance(ray, scene, ctx, true, alpha, &hitDistance);
}

RenderResult PathIntegrator::renderSamples(const RenderInputs& in, Film& film,
                                           const RenderOptions& options) {
  SampleLoop loop = sampleLoop(in, film);
  loop.firstHit = this;
  return renderPixelSamples(in, film, options, loop);
}

Spectrum PathIntegrator::LiFromFirstHit(const RayDifferential& ray, SurfaceInteraction* hit,
                                        Float tHit, const Scene& scene, IntegratorContext& ctx,
                                        Float* alpha) const {
  Float hitDistance;
  FirstHit first{hit, tHit};
  return radiance(ray, scene, ctx, true, alpha, &hitDistance, &first);
}

Spectrum PathIntegrator::scatteredLi(const RayDifferential& ray, const Scene& scene,
                                     IntegratorContext& ctx, Float* hitDistance) const {
  Float alpha;
  return radiance(ray, scene, ctx, false, &alpha, hitDistance);
}

// One ray per strategy and vertex (pbrt 4e §13.4): the direction the BSDF samples to continue the
// path is also the BSDF strategy of next-event estimation. Emission the path meets after a
// non-specular bounce is weighted against the light strategy's density of that direction, the
// light sample at each vertex against the BSDF's; a light the path meets after a specular bounce,
// or after a vertex that sampled no light, counts in full.
Spectrum PathIntegrator::radiance(const RayDifferential& cameraRay, const Scene& scene,
                                  IntegratorContext& ctx, bool firstEmission, Float* alpha,
                                  Float* hitDistance, const FirstHit* first) const {
  Spectrum l(0), beta(1);
  // Training: the vertices whose incident radiance the path records.
  GuidePathRecorder records(recording(), maxDepth_, ctx.arena);
  auto gather = [&](const Spectrum& light) {
    l += light;
    records.gather(light);
  };
  // The radiance scaling of the refractions the path passed, which the roulette leaves out.
  Float etaScale = 1;
  RayDifferential ray(cameraRay);
  bool specularBounce = false;
  // The vertex the current ray left and the BSDF's density of its direction there.
  Interaction previous;
  Float scatteringPdf = 0;
  const Float lightChoicePdf = scene.lights().empty() ? 0 : 1 / Float(scene.lights().size());
  *alpha = 0;
  for (int bounces = 0;; ++bounces) {
    // Not zeroed: intersect writes every member on a hit, and a miss ends the path unread.
    SurfaceInteraction own(kUninitialized);
    Float tMax = ray.tMax;  // intersect shortens ray.tMax to the hit
    // The camera ray's hit may be the caller's, found as intersect finds it (used once: a media
    // interface continues the camera ray at bounces 0 again).
    const bool given = first != nullptr;
    bool hit = given ? first->isect != nullptr : scene.intersect(ray, &own, ctx.stats);
    if (given && hit) ray.tMax = first->t;
    SurfaceInteraction& isect = given && hit ? *first->isect : own;
    first = nullptr;
    // A segment after a bounce crosses the scene's volume (the camera ray's: the renderer's).
    // (Skipped without a volume, where it is 1 and only costs the multiplications.)
    if (bounces > 0 && scene.volume()) beta *= volumeTransmittance(ray, scene, ctx);
    if (bounces == 0) {
      *alpha = hit ? 1 : 0;
      *hitDistance = hit ? ray.tMax : kInfinity;
    }
    if (bounces > 0 || firstEmission) {
      // After a non-specular bounce the light strategy could have sampled the same direction.
      bool weighted = bounces > 0 && !specularBounce;
      auto misWeight = [&](const Light& light) {
        if (!weighted) return Float(1);
        Float choicePdf = lightSampler_ ? lightSampler_->pmf(LightSampleContext(previous), light)
                                        : lightChoicePdf;
        Float lightPdf = choicePdf * light.pdfLi(previous, ray.d);
        return powerHeuristic(1, scatteringPdf, 1, lightPdf);
      };
      if (hit) {
        if (const AreaLight* area = isect.primitive->areaLight) {
          Spectrum le = area->L(isect, -ray.d);
          if (!le.isBlack()) gather(beta * le * misWeight(*area));
        }
      } else {
        for (const Light* light : scene.lights()) {
          Spectrum le = light->Le(ray);
          if (!le.isBlack()) gather(beta * le * misWeight(*light));
        }
      }
    }
    if (!hit || bounces >= maxDepth_) break;
    const Primitive& prim = *isect.primitive;
    if (!prim.material) {
      // An interface between media: the path goes on unchanged, from the same vertex.
      ray = continueThrough(isect, ray, tMax);
      --bounces;
      continue;
    }
    if (bounces == 0) isect.computeDifferentials(ray);
    const BSDF* bsdf = prim.material->getBSDF(isect, ctx.arena);
    bool sampledLight = bsdf->numComponents(kAllBxDF & ~kSpecular) > 0;
    // The sampler's values in the order of a vertex: the light's choice and sample, then the
    // BSDF's (a heterogeneous volume's march along the shadow segment draws its offset after).
    Float uChoice = 0;
    Point2f uLight;
    if (sampledLight) {
      uChoice = ctx.get1D();
      uLight = ctx.get2D();
    }
    Vector3f wi;
    BxDFType sampledType;
    // The value that picks a component; a BSDF of one component that makes no choice of its own
    // does not read it (a lone Lambertian, most vertices), so it is passed over there.
    Float uComponent = 0;
    if (bsdf->readsComponentValue())
      uComponent = ctx.get1D();
    else
      ctx.skip1D();
    const Point2f uScattering = ctx.get2D();
    // Guiding: the field's distribution here (guidedMixture). Its value is drawn at every vertex
    // of a guided render.
    const Float uMix = guide() ? ctx.get1D() : 0;
    const ScatteringMixture mixture =
        guide() ? guidedMixture(guide(), *bsdf, isect.p) : ScatteringMixture();
    // The next direction before the light sample, which it does not depend on: its chain of
    // divisions and series then overlaps the light sample's work rather than following it.
    const Spectrum f = mixture.guide ? mixture.sample(*bsdf, isect.wo, uComponent, uScattering,
                                                      uMix, &wi, &scatteringPdf, &sampledType)
                                     : bsdf->sampleF(isect.wo, &wi, uComponent, uScattering,
                                                     &scatteringPdf, kAllBxDF, &sampledType);
    const ScatteringMixture* mix = mixture.guide ? &mixture : nullptr;
    if (sampledLight) {
      if (!lightSampler_) {
        gather(beta * sampleOneLightAgainstBSDF(isect, *bsdf, scene, ctx, uChoice, uLight, mix));
      } else {
        Float choicePdf = 0;
        if (const Light* light =
                lightSampler_->sample(LightSampleContext(isect), uChoice, &choicePdf))
          gather(beta *
                 sampleLightAgainstBSDF(isect, *bsdf, *light, choicePdf, scene, ctx, uLight, mix));
      }
    }
    if (f.isBlack() || scatteringPdf == 0) break;
    beta *= f * (absDot(wi, bsdf->shadingNormal()) / scatteringPdf);
    specularBounce = (sampledType & kSpecular) != 0 || !sampledLight;
    if (records.active() && !specularBounce)
      records.add(isect.p, wi, scatteringPdf, absDot(wi, bsdf->shadingNormal()), beta);
    if ((sampledType & kSpecular) && (sampledType & kTransmission)) {
      // A refraction scales beta by 1 / eta^2 when the path goes in (wo on the side the normal
      // points to) and by eta^2 when it comes out (pbrt 3e §8.2.3); etaScale undoes that.
      Float eta2 = bsdf->eta * bsdf->eta;
      etaScale *= dot(isect.wo, isect.n) > 0 ? eta2 : 1 / eta2;
    }
    previous = isect;
    // The next segment, its differentials off: those left in ray are never read (every reader
    // tests hasDifferentials), so need no zeroing.
    static_cast<Ray&>(ray) = isect.spawnRay(wi);
    ray.hasDifferentials = false;

    // Russian roulette: continue with probability tied to the throughput (pbrt 2e §15.3 uses
    // min(0.5, y); the throughput's largest channel wastes less on coloured paths), taken
    // without the radiance scaling of refractions under both rules: inside glass beta is 1/eta^2
    // of the light the path carries out again, and pbrt-v2's rule, which does not undo that,
    // kills paths there with probability 0.56 and weighs the survivors 2.3x (with pbrt-v2's
    // rule the Cornell box with a glass sphere had twice pbrt-v3's error per sample). Not
    // before the last segment, which only looks for emission: it would add variance to save one
    // ray. pbrt-v3's rule (path.h) spares paths whose eta-scaled throughput reaches rrthreshold.
    if (bounces >= rrStartDepth_ && bounces + 1 < maxDepth_) {
      Float survival = beta.maxComponent() * etaScale;
      bool faces = true;
      if (settings_.pbrtV3Roulette) {
        faces = survival < settings_.rrThreshold;
      }
      if (faces) {
        Float q = std::max(Float(0.05), 1 - survival);
        if (ctx.get1D() < q) break;
        beta /= 1 - q;
      }
    }
    if (!beta.isFinite()) break;
  }
  if (records.active()) records.flush(*guide());
  return l;
}

}  // namespace candela
