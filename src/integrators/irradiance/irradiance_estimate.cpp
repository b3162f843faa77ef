#include "integrators/irradiance/irradiance_estimate.h"

#include <algorithm>
#include <vector>

#include "core/sampling.h"
#include "samplers/random_sampler.h"
#include "samplers/zero_two_sequence.h"

namespace candela {

IrradianceEstimate estimateIrradiance(const IrradianceQuery& query, const Scene& scene,
                                      const PathIntegrator& paths, int nSamples, int nFilter,
                                      uint64_t seed, RayStats& stats) {
  Vector3f n(query.n), s, t;
  coordinateSystem(n, &s, &t);
  RNG rng(seed, mixBits(seed));
  uint32_t scrambleX = rng.uniformUInt32(), scrambleY = rng.uniformUInt32();
  // Each ray's path draws from its own stream: sample index i of a sampler keyed by the seed.
  RandomSampler sampler(1, mixBits(seed ^ 0x5bd1e995u));
  MemoryArena arena;
  IntegratorContext ctx{sampler, arena, stats};
  std::vector<Spectrum> radiance(static_cast<size_t>(nSamples));
  IrradianceEstimate est;
  double sumInverseDistance = 0;
  for (int i = 0; i < nSamples; ++i) {
    Point2f u(bitsToUnitFloat(vanDerCorputBits(uint32_t(i), scrambleX)),
              bitsToUnitFloat(sobol2Bits(uint32_t(i), scrambleY)));
    Vector3f local = sampleCosineHemisphere(u);
    Vector3f w = s * local.x + t * local.y + n * local.z;
    sampler.startPixelSample(Point2i(0, 0), i);
    Float hitDistance;
    radiance[size_t(i)] =
        paths.scatteredLi(RayDifferential(query.at.spawnRay(w)), scene, ctx, &hitDistance);
    arena.reset();
    if (!radiance[size_t(i)].isFinite()) radiance[size_t(i)] = Spectrum(0);
    if (hitDistance < kInfinity && hitDistance > 0) sumInverseDistance += 1 / double(hitDistance);
    est.minHitDistance = std::min(est.minHitDistance, hitDistance);
  }
  if (sumInverseDistance > 0) est.harmonicMeanDistance = Float(nSamples / sumInverseDistance);
  auto kept = radiance.end() - nFilter;
  if (nFilter > 0)
    std::nth_element(radiance.begin(), kept, radiance.end(),
                     [](const Spectrum& a, const Spectrum& b) { return a.y() < b.y(); });
  Spectrum sum(0);
  for (auto it = radiance.begin(); it != kept; ++it) sum += *it;
  est.E = sum * (kPi / Float(nSamples - nFilter));
  return est;
}

Float validityRadius(const IrradianceEstimate& estimate, Float pixelSpacing,
                     const IrradianceCacheSettings& settings, Float sceneSize) {
  Float r =
      std::min(settings.maxError * estimate.harmonicMeanDistance, estimate.minHitDistance / 2);
  if (pixelSpacing > 0 && pixelSpacing < kInfinity)
    r = std::clamp(r, settings.minPixelSpacing * pixelSpacing,
                   settings.maxPixelSpacing * pixelSpacing);
  return std::min(r, sceneSize);
}

}  // namespace candela
