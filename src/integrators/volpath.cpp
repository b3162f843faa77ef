#include "integrators/volpath.h"

#include "accel/primitive.h"
#include "core/rng.h"
#include "core/sampling.h"
#include "materials/material.h"
#include "media/medium_interface.h"
#include "media/tracking.h"
#include "transport/guide_recorder.h"
#include "transport/light_sampling.h"
#include "transport/specular_differentials.h"

namespace candela {

namespace {

constexpr int kNonSpecular = kAllBxDF & ~kSpecular;
// A path or shadow ray crosses at most this many pure interfaces in a row (a guard against a
// ray stuck on a surface; never reached in a sound scene).
constexpr int kMaxInterfaceCrossings = 1024;

// The media along a path: the scene-filling pbrt-v2 volume when there is one, else pbrt-v3's
// named media changing at interfaces.
struct MediaRules {
  const Medium* fill;
  // The medium a ray leaving isect in direction w travels through, coming from `current`.
  const Medium* after(const SurfaceInteraction& isect, const Vector3f& w,
                      const Medium* current) const {
    if (fill) return fill;
    const MediumInterface* mi = isect.primitive ? isect.primitive->mediumInterface : nullptr;
    return mi ? mi->entered(w, isect.n) : current;
  }
};

// What scatters at a path vertex: a BSDF (f includes |cos θi|) or a phase function.
struct Scatterer {
  const BSDF* bsdf = nullptr;
  PhaseFunction phase;
  Spectrum f(const Vector3f& wo, const Vector3f& wi) const {
    if (bsdf) return bsdf->f(wo, wi, kNonSpecular) * absDot(wi, bsdf->shadingNormal());
    return Spectrum(phase.p(wo, wi));
  }
  Float pdf(const Vector3f& wo, const Vector3f& wi) const {
    return bsdf ? bsdf->pdf(wo, wi, kNonSpecular) : phase.pdf(wo, wi);
  }
  Spectrum sample(const Vector3f& wo, Float uComponent, const Point2f& u, Vector3f* wi,
                  Float* pdf) const {
    if (bsdf) {
      BxDFType type;
      Spectrum f = bsdf->sampleF(wo, wi, uComponent, u, pdf, kNonSpecular, &type);
      return f * absDot(*wi, bsdf->shadingNormal());
    }
    Float ratio = phase.sample(wo, u, wi, pdf);
    return Spectrum(ratio * *pdf);
  }
};

struct PathState {
  const Scene& scene;
  MediaRules media;
  RNG& rng;
  RayStats& stats;
  const LightSampler* lightSampler;  // null: uniform
  bool hittableLights;               // some light is not a delta: scattering samples can meet it
};

// Transmittance from `from` to `to` in `medium` (the one the segment starts in), through pure
// interfaces; 0 when a surface with a material blocks it.
Spectrum shadowTransmittance(const Interaction& from, const Interaction& to, const Medium* medium,
                             PathState& s) {
  Spectrum tr(1);
  Ray ray = from.spawnRayTo(to);
  for (int crossing = 0; crossing < kMaxInterfaceCrossings; ++crossing) {
    SurfaceInteraction isect;
    bool hit = s.scene.intersect(ray, &isect, s.stats);
    if (hit && isect.primitive->material) return Spectrum(0);
    if (medium) tr *= trackedTransmittance(*medium, ray, s.rng);
    if (!hit) return tr;
    if (tr.isBlack()) return tr;
    medium = s.media.after(isect, ray.d, medium);
    ray = isect.spawnRayTo(to);
  }
  return Spectrum(0);
}

// The probability with which sampleOneLight chooses light at p.
Float choiceProbability(const PathState& s, const Interaction& at, const Light& light) {
  return s.lightSampler ? s.lightSampler->pmf(LightSampleContext(at), light)
                        : 1 / Float(s.scene.lights().size());
}

// The BSDF or phase strategy's share of the direct light: the emission that the ray leaving
// `from` in direction w (unit) meets first, with the transmittance on the way, through pure
// interfaces (whose emission is collected as it is crossed, as light sampling sees through them),
// stopping at the first surface with a material. Each light's emission is weighted by the power
// heuristic of scatteringPdf against the light strategy's density of w for it: its choice
// probability times its own density (pbrt 4e §13.4). Emission of any light counts, not only of
// the one the light strategy chose: a light made of many triangles is many lights, and counting
// only the chosen one's would throw most hits away.
Spectrum emissionAlong(const Interaction& from, const Vector3f& w, const Medium* medium,
                       Float scatteringPdf, PathState& s) {
  auto weighted = [&](const Light& light, const Spectrum& le) {
    Float lightPdf = choiceProbability(s, from, light) * light.pdfLi(from, w);
    return le * powerHeuristic(1, scatteringPdf, 1, lightPdf);
  };
  Spectrum tr(1), le(0);
  Ray ray = from.spawnRay(w);
  for (int crossing = 0; crossing < kMaxInterfaceCrossings; ++crossing) {
    SurfaceInteraction isect;
    bool hit = s.scene.intersect(ray, &isect, s.stats);
    if (medium) tr *= trackedTransmittance(*medium, ray, s.rng);
    if (tr.isBlack()) return le;
    if (!hit) {
      for (const Light* light : s.scene.lights()) {
        Spectrum e = light->Le(RayDifferential(ray));
        if (!e.isBlack()) le += tr * weighted(*light, e);
      }
      return le;
    }
    const Primitive& prim = *isect.primitive;
    if (prim.areaLight) {
      Spectrum e = prim.areaLight->L(isect, -w);
      if (!e.isBlack()) le += tr * weighted(*prim.areaLight, e);
    }
    if (prim.material) return le;
    medium = s.media.after(isect, ray.d, medium);
    ray = isect.spawnRay(ray.d);
  }
  return le;
}

// Direct light at `it` (pbrt 3e §14.3.1, §15.3.1): a sample of one light, chosen uniformly or by
// the light sampler, and a BSDF or phase sample, combined by the power heuristic with the light
// strategy's density taken as the choice's probability times the light's density (so that the
// scattering sample may count whichever light it meets), each with its transmittance.
// shadowMedium(w) is the medium a ray leaving it in direction w starts in.
template <typename ShadowMedium>
Spectrum sampleOneLight(const Interaction& it, const Scatterer& scatterer,
                        const ShadowMedium& shadowMedium, PathState& s, Sampler& sampler) {
  int nLights = int(s.scene.lights().size());
  Float uChoice = sampler.get1D();
  Point2f uLight = sampler.get2D();
  Point2f uScattering = sampler.get2D();
  Float uComponent = sampler.get1D();
  if (nLights == 0) return Spectrum(0);
  Float choicePdf = 1 / Float(nLights);
  const Light* chosen = s.lightSampler
                            ? s.lightSampler->sample(LightSampleContext(it), uChoice, &choicePdf)
                            : s.scene.lights()[std::min(int(uChoice * nLights), nLights - 1)];
  Spectrum ld(0);
  Vector3f wi;
  if (chosen && choicePdf > 0) {
    const Light& light = *chosen;
    Float lightPdf = 0;
    VisibilityTester vis;
    Spectrum li = light.sampleLi(it, uLight, &wi, &lightPdf, &vis);
    if (lightPdf > 0 && !li.isBlack()) {
      Spectrum f = scatterer.f(it.wo, wi);
      if (!f.isBlack()) {
        Spectrum tr = shadowTransmittance(vis.p0, vis.p1, shadowMedium(wi), s);
        if (!tr.isBlack()) {
          Float pdf = choicePdf * lightPdf;
          Float weight = light.isDelta() ? 1 : powerHeuristic(1, pdf, 1, scatterer.pdf(it.wo, wi));
          ld += f * li * tr * (weight / pdf);
        }
      }
    }
  }
  if (s.hittableLights) {
    Float scatteringPdf = 0;
    Spectrum f = scatterer.sample(it.wo, uComponent, uScattering, &wi, &scatteringPdf);
    if (!f.isBlack() && scatteringPdf > 0) {
      Spectrum le = emissionAlong(it, wi, shadowMedium(wi), scatteringPdf, s);
      if (!le.isBlack()) ld += f * le / scatteringPdf;
    }
  }
  return ld;
}

// A per-path generator for the tracking decisions, seeded from two sampler dimensions (so a
// function of pixel, sample index and seed).
RNG pathRng(Sampler& sampler) {
  uint64_t a = uint64_t(double(sampler.get1D()) * 4294967296.0);
  uint64_t b = uint64_t(double(sampler.get1D()) * 4294967296.0);
  return RNG((a << 32) ^ b);
}

}  // namespace

void VolPathIntegrator::preprocess(const Scene& scene, const PreprocessOptions& options) {
  if (std::string notice = lightStrategyNotice(lightStrategy_, scene.lights().size());
      !notice.empty() && options.warn)
    options.warn(notice);
  hittableLights_ = false;
  for (const Light* light : scene.lights()) hittableLights_ = hittableLights_ || !light->isDelta();
  lightSampler_.reset();
  if (lightStrategy_ != LightSampleStrategy::Uniform)
    lightSampler_ = createLightSampler(lightStrategy_, scene.lights(), scene.worldBound());
}

Spectrum VolPathIntegrator::Li(const RayDifferential& cameraRay, const Scene& scene,
                               IntegratorContext& ctx, Float* alpha) const {
  RNG rng = pathRng(ctx.sampler);
  PathState s{scene,     MediaRules{scene.volume()}, rng,
              ctx.stats, lightSampler_.get(),        hittableLights_};
  const Medium* medium = scene.volume() ? scene.volume() : scene.media().camera;
  Spectrum l(0), beta(1);
  // Training: the surface vertices whose incident radiance the path records.
  GuidePathRecorder records(recording(), maxDepth_, ctx.arena);
  auto gather = [&](const Spectrum& light) {
    l += light;
    records.gather(light);
  };
  const GuidingField* guide = this->guide();
  RayDifferential ray(cameraRay);
  bool specularBounce = false;
  Float etaScale = 1;  // the radiance scaling of the refractions passed, for the roulette
  bool firstSegment = true;
  *alpha = 0;
  int bounces = 0;
  int crossings = 0;  // pure interfaces crossed since the last scattering
  for (;;) {
    SurfaceInteraction isect;
    Float tMax = ray.tMax;  // intersect shortens ray.tMax to the hit
    bool hit = scene.intersect(ray, &isect, ctx.stats);
    FreeFlight flight;
    if (medium) {
      flight = sampleFreeFlight(*medium, ray, rng, beta);
      if (!flight.emitted.isBlack()) gather(beta * flight.emitted);
      beta *= flight.weight;
    }
    if (firstSegment) *alpha = (hit || flight.scattered) ? 1 : 0;
    firstSegment = false;
    if (beta.isBlack()) break;

    if (flight.scattered) {
      // A real collision in the medium (pbrt 3e §15.3): next-event estimation with the phase
      // function, then a new direction from it.
      if (bounces >= maxDepth_) break;
      Interaction mi(ray(flight.t), ray.time);
      mi.wo = -normalize(ray.d);
      Scatterer phase{nullptr, medium->phase(mi.p, ray.time)};
      const Medium* here = medium;
      gather(beta * sampleOneLight(
                        mi, phase, [here](const Vector3f&) { return here; }, s, ctx.sampler));
      Vector3f wi;
      Float pdf;
      Float ratio = phase.phase.sample(mi.wo, ctx.sampler.get2D(), &wi, &pdf);
      if (!(pdf > 0) || ratio == 0) break;
      beta *= ratio;
      ray = RayDifferential(mi.spawnRay(wi));
      specularBounce = false;
      ++bounces;
      crossings = 0;
    } else {
      // Emission is counted here only where next-event estimation could not have sampled it.
      if (bounces == 0 || specularBounce) {
        if (hit) {
          if (isect.primitive->areaLight)
            gather(beta * isect.primitive->areaLight->L(isect, -ray.d));
        } else {
          for (const Light* light : scene.lights()) gather(beta * light->Le(ray));
        }
      }
      if (!hit) break;
      const Primitive& prim = *isect.primitive;
      if (!prim.material) {
        // A pure interface: the path goes on unchanged in the medium on the other side.
        if (++crossings > kMaxInterfaceCrossings) break;
        medium = s.media.after(isect, ray.d, medium);
        ray = continueThrough(isect, ray, tMax);
        continue;
      }
      if (bounces >= maxDepth_) break;
      if (bounces == 0) isect.computeDifferentials(ray);
      const BSDF* bsdf = prim.material->getBSDF(isect, ctx.arena);
      Scatterer surface{bsdf, PhaseFunction()};
      if (bsdf->numComponents(kNonSpecular) > 0) {
        const Medium* current = medium;
        const MediaRules& rules = s.media;
        gather(beta * sampleOneLight(
                          isect, surface,
                          [&](const Vector3f& w) { return rules.after(isect, w, current); }, s,
                          ctx.sampler));
      }
      Vector3f wi;
      Float pdf;
      BxDFType sampledType;
      Spectrum f;
      if (const ScatteringMixture mixture = guidedMixture(guide, *bsdf, isect.p); !mixture.guide) {
        f = bsdf->sampleF(isect.wo, &wi, ctx.sampler.get1D(), ctx.sampler.get2D(), &pdf, kAllBxDF,
                          &sampledType);
      } else {
        // One sample of the mixture of the BSDF and the field (values drawn in a fixed order).
        Float uComponent = ctx.sampler.get1D();
        Point2f u = ctx.sampler.get2D();
        Float uMix = ctx.sampler.get1D();
        f = mixture.sample(*bsdf, isect.wo, uComponent, u, uMix, &wi, &pdf, &sampledType);
      }
      if (f.isBlack() || pdf == 0) break;
      beta *= f * (absDot(wi, bsdf->shadingNormal()) / pdf);
      specularBounce = (sampledType & kSpecular) != 0;
      if (records.active() && !specularBounce)
        records.add(isect.p, wi, pdf, absDot(wi, bsdf->shadingNormal()), beta);
      if ((sampledType & kSpecular) && (sampledType & kTransmission)) {
        // A refraction scales beta by 1 / eta^2 going in and eta^2 coming out (pbrt 3e §8.2.3);
        // the roulette below looks at beta without that scaling, as pbrt-v3's volpath does.
        Float eta2 = bsdf->eta * bsdf->eta;
        etaScale *= dot(isect.wo, isect.n) > 0 ? eta2 : 1 / eta2;
      }
      medium = s.media.after(isect, wi, medium);
      ray = RayDifferential(isect.spawnRay(wi));
      ++bounces;
      crossings = 0;
    }

    // Russian roulette once the throughput is small (pbrt 3e §14.5.1, volpath's rule), the
    // throughput taken without the radiance scaling of the refractions the path passed.
    Float survival = beta.maxComponent() * etaScale;
    if (bounces > 3 && survival < rrThreshold_) {
      Float q = std::max(Float(0.05), 1 - survival);
      if (ctx.sampler.get1D() < q) break;
      beta /= 1 - q;
    }
    if (!beta.isFinite()) break;
  }
  if (records.active()) records.flush(*this->guide());
  return l;
}

}  // namespace candela
