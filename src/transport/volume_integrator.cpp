#include "transport/volume_integrator.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/rng.h"

namespace candela {

namespace {

// Beyond this many steps a ray is marched in this many (a huge scene with a tiny stepsize would
// otherwise take hours per ray or overflow the count).
constexpr int kMaxSteps = 1 << 20;

// exp(-τ) of the part of ray's segment [0, ray.tMax] inside the medium.
Spectrum segmentTransmittance(const Medium& medium, const Ray& ray, Float stepSize, Float offset) {
  Float t0, t1;
  if (!medium.intersectP(ray, &t0, &t1)) return Spectrum(1);
  return exp(-medium.opticalDepth(ray, t0, t1, stepSize, offset));
}

uint64_t bitsOf(Float u) {
  uint64_t bits = 0;
  std::memcpy(&bits, &u, sizeof u);
  return bits;
}

}  // namespace

Spectrum VolumeIntegrator::Li(const Ray& ray, const Scene& scene, IntegratorContext& ctx,
                              Spectrum* transmittance) const {
  const Medium* volume = scene.volume();
  Float t0, t1;
  if (!volume || !volume->intersectP(ray, &t0, &t1)) {
    *transmittance = Spectrum(1);
    return Spectrum(0);
  }
  // The marching offset comes from the sampler (lrt draft §16.7.1); what each step needs besides
  // (sub-step offsets, Russian roulette, light choice) from a generator seeded by the sampler.
  Float offset = ctx.sampler.get1D();
  RNG rng(hashValues({bitsOf(ctx.sampler.get1D()), bitsOf(offset)}));
  *transmittance = exp(-volume->opticalDepth(ray, t0, t1, stepSize_, offset));
  if (!hasSource(*volume)) return Spectrum(0);

  Float dLength = ray.d.length();
  Float length = (t1 - t0) * dLength;
  int n = int(std::min(std::ceil(double(length) / double(stepSize_)), double(kMaxSteps)));
  n = std::max(n, 1);
  Float dt = (t1 - t0) / Float(n);
  Vector3f wo = -ray.d / dLength;
  Spectrum tr(1), lv(0);
  Float tPrev = t0;
  for (int i = 0; i < n; ++i) {
    Float t = t0 + (Float(i) + offset) * dt;
    // Transmittance from the ray's origin to ray(t), one step at a time (half-steps for media
    // that march).
    tr *= exp(-volume->opticalDepth(ray, tPrev, t, stepSize_ / 2, rng.uniformFloat()));
    tPrev = t;
    // Once little gets through, continue with probability 1/2 (lrt draft §16.7.1).
    if (tr.maxComponent() < Float(1e-3)) {
      if (rng.uniformFloat() > Float(0.5)) break;
      tr /= Float(0.5);
    }
    Point3f p = ray(t);
    MediumPoint m = volume->at(p, ray.time);
    lv += tr * source(p, ray.time, m, wo, scene, ctx, rng);
  }
  return lv * (dt * dLength);
}

Spectrum VolumeIntegrator::transmittance(const Ray& ray, const Scene& scene,
                                         IntegratorContext& ctx) const {
  const Medium* volume = scene.volume();
  if (!volume) return Spectrum(1);
  // Closed-form media ignore the offset; others march with a random one (lrt draft §16.7.1).
  Float offset = volume->isHomogeneous() ? Float(0.5) : ctx.sampler.get1D();
  return segmentTransmittance(*volume, ray, 4 * stepSize_, offset);
}

Spectrum SingleScatteringIntegrator::source(const Point3f& p, Float time, const MediumPoint& m,
                                            const Vector3f& wo, const Scene& scene,
                                            IntegratorContext& ctx, RNG& rng) const {
  Spectrum s = m.Le;
  const std::vector<const Light*>& lights = scene.lights();
  if (m.sigmaS.isBlack() || lights.empty()) return s;
  int nLights = int(lights.size());
  int index = std::min(int(rng.uniformFloat() * Float(nLights)), nLights - 1);
  Point2f uLight(rng.uniformFloat(), rng.uniformFloat());
  Interaction it(p, time);
  it.wo = wo;
  Vector3f wi;
  Float pdf = 0;
  VisibilityTester vis;
  Spectrum li = lights[size_t(index)]->sampleLi(it, uLight, &wi, &pdf, &vis);
  if (!(pdf > 0) || li.isBlack()) return s;
  const Medium& volume = *scene.volume();
  Float phase = volume.phase(p, time).p(wo, wi);
  if (phase == 0 || !scene.unoccluded(vis, ctx.stats)) return s;
  Ray toLightSegment(p, vis.p1.p - p, 1, time);
  Spectrum toLight =
      segmentTransmittance(volume, toLightSegment, 4 * stepSize(), rng.uniformFloat());
  return s + m.sigmaS * li * toLight * (phase * Float(nLights) / pdf);
}

}  // namespace candela
