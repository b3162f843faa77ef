#include "integrators/path.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "accel/primitive.h"
#include "core/sampling.h"
#include "integrators/progressive_render.h"
#include "materials/material.h"
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

int guidingTrainingSamples(int samplesPerPixel) {
  int t = 0;
  while (samplesPerPixel >= 4 * std::max(1, 2 * t)) t = std::max(1, 2 * t);
  return t;
}

ProgressiveResult PathIntegrator::render(const RenderInputs& in, Film& film,
                                         const ProgressiveOptions& options) {
  if (!settings_.guiding) return PixelSampleIntegrator::render(in, film, options);
  return renderGuided(in, film, options);
}

ProgressiveResult PathIntegrator::renderGuided(const RenderInputs& in, Film& film,
                                               const ProgressiveOptions& options) {
  if (options.adaptive.enabled())
    throw std::runtime_error(
        "path guiding does not yet combine with adaptive sampling (--noise-threshold or the "
        "Film's \"noisethreshold\"): use one of them");
  const int spp = in.sampler.samplesPerPixel();
  const int trained = guidingTrainingSamples(spp);
  // The samples the film takes: options.render's range.
  const int first = std::max(0, options.render.firstSample);
  const int end = options.render.endSample < 0 ? spp : std::min(options.render.endSample, spp);
  guide_ = std::make_unique<GuidingField>(in.scene.worldBound());
  int finished = 0;
  auto renderPass = [&](const RenderOptions& pass) {
    SampleLoop loop = sampleLoop(in, film);
    loop.firstHit = this;
    if (pass.endSample <= trained) {
      // Training: the full image, every sample; the film keeps those of its range and crop.
      loop.pixels = Bounds2i(Point2i(0, 0), film.fullResolution());
      loop.filmFirstSample = first;
      loop.filmEndSample = end;
      recording_ = true;
      RenderResult r;
      try {
        r = renderPixelSamples(in, film, pass, loop);
      } catch (...) {
        recording_ = false;
        throw;
      }
      recording_ = false;
      guide_->finishPass(finished++);
      return r;
    }
    RenderOptions own = pass;
    own.firstSample = std::max(pass.firstSample, first);
    own.endSample = std::min(pass.endSample, end);
    if (own.firstSample >= own.endSample) return RenderResult();
    return renderPixelSamples(in, film, own, loop);
  };
  std::vector<int> ends = doublingPassEnds(spp);
  if (options.afterPass || options.timeBudget > 0) return renderPasses(renderPass, ends, options);
  // One pass after the training ones.
  while (!ends.empty() && ends.back() > trained) ends.pop_back();
  ends.push_back(spp);
  ProgressiveResult result;
  for (size_t i = 0; i < ends.size(); ++i) {
    RenderOptions pass = options.render;
    pass.firstSample = i == 0 ? 0 : ends[i - 1];
    pass.endSample = ends[i];
    if (i + 1 < ends.size()) pass.quiet = true;
    result.total.add(renderPass(pass));
  }
  result.spp = spp;
  result.passes = 1;
  return result;
}

std::string PathIntegrator::statsReport() const {
  if (!guide_) return {};
  return "Path guiding: " + std::to_string(guide_->passesFinished()) + " training passes, " +
         std::to_string(guide_->leaves()) + " spatial leaves\n";
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

namespace {
// Müller et al. 2017's fixed share of BSDF sampling in the guided mixture (§5.1).
constexpr Float kGuidedBsdfShare = 0.5f;

// A non-specular vertex of a training path: the radiance arriving there along the direction the
// path took is the light the path gathers after it, over the throughput up to and with the
// vertex's scattering (beta), not counting the vertex's own roulette (so it stays unbiased). The
// field learns that radiance times the cosine at the vertex: for a diffuse surface the product
// the integrand is proportional to. Learning the radiance alone (Müller et al. 2017) left the
// indirect room at --quick at 2.4 times the relMSE at 256 spp (0.083 against 0.035).
struct GuideRecord {
  Point3f p;
  Vector3f wi;
  Float pdf;
  Float cosine;
  Spectrum beta;
  Spectrum radiance;
};

// The most vertices a path records: the cost of adding light to them grows with their square.
constexpr int kMostGuideRecords = 64;

Spectrum over(const Spectrum& light, const Spectrum& beta) {
  Spectrum r(0);
  for (int c = 0; c < 3; ++c)
    if (beta[c] > 0) r[c] = light[c] / beta[c];
  return r;
}
}  // namespace

// One ray per strategy and vertex (pbrt 4e §13.4): the direction the BSDF samples to continue the
// path is also the BSDF strategy of next-event estimation. Emission the path meets after a
// non-specular bounce is weighted against the light strategy's density of that direction, the
// light sample at each vertex against the BSDF's; a light the path meets after a specular bounce,
// or after a vertex that sampled no light, counts in full.
Spectrum PathIntegrator::radiance(const RayDifferential& cameraRay, const Scene& scene,
                                  IntegratorContext& ctx, bool firstEmission, Float* alpha,
                                  Float* hitDistance, const FirstHit* first) const {
  Spectrum l(0), beta(1);
  // Training: the vertices whose incident radiance the path records, and light it gathers added
  // to each of them.
  const int mostRecords = std::min(maxDepth_, kMostGuideRecords);
  GuideRecord* records =
      recording_
          ? static_cast<GuideRecord*>(ctx.arena.alloc(sizeof(GuideRecord) * size_t(mostRecords)))
          : nullptr;
  int nRecords = 0;
  auto gather = [&](const Spectrum& light) {
    l += light;
    for (int i = 0; i < nRecords; ++i) records[i].radiance += over(light, records[i].beta);
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
    // Guiding: the field's distribution here, at a vertex with no specular lobe (a delta has no
    // density to mix), once trained. Its value is drawn at every vertex of a guided render.
    ScatteringMixture mixture;
    const Float uMix = guide_ ? ctx.get1D() : 0;
    if (guide_ && sampledLight &&
        bsdf->numComponents() == bsdf->numComponents(kAllBxDF & ~kSpecular))
      if (const DirectionalQuadtree& d = guide_->at(isect.p); d.trained())
        mixture = {&d, kGuidedBsdfShare};
    // The next direction before the light sample, which it does not depend on: its chain of
    // divisions and series then overlaps the light sample's work rather than following it.
    Spectrum f;
    if (!mixture.guide) {
      f = bsdf->sampleF(isect.wo, &wi, uComponent, uScattering, &scatteringPdf, kAllBxDF,
                        &sampledType);
    } else {
      // One sample of the mixture; both branches evaluate the BSDF as the light strategy does.
      Float guidePdf = 0;
      bool sampled = true;
      if (uMix < mixture.bsdfShare) {
        bsdf->sampleF(isect.wo, &wi, uComponent, uScattering, &scatteringPdf, kAllBxDF,
                      &sampledType);
        sampled = scatteringPdf > 0;
      } else {
        wi = mixture.guide->sample(uScattering, &guidePdf);
      }
      sampledType = BxDFType(kDiffuse);
      f = sampled ? bsdf->f(isect.wo, wi) : Spectrum(0);
      scatteringPdf = sampled ? mixture.pdf(*bsdf, isect.wo, wi, kAllBxDF) : 0;
    }
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
    if (records && !specularBounce && nRecords < mostRecords)
      records[nRecords++] = {isect.p, wi,         scatteringPdf, absDot(wi, bsdf->shadingNormal()),
                             beta,    Spectrum(0)};
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
  for (int i = 0; i < nRecords; ++i) {
    const GuideRecord& r = records[i];
    guide_->record(r.p, r.wi, double(r.radiance.y()) * r.cosine / r.pdf);
  }
  return l;
}

}  // namespace candela
