#include "transport/virtual_point_lights.h"

#include <array>

#include "accel/primitive.h"
#include "core/memory.h"
#include "core/rng.h"
#include "core/sampling.h"
#include "materials/material.h"
#include "reflection/bsdf.h"
#include "reflection/bxdf.h"
#include "samplers/radical_inverse.h"
#include "transport/light_paths.h"
#include "transport/scattering_surface.h"

namespace candela {

namespace {

// Light paths are ended by Russian roulette; this only stops a path in a scene that reflects
// all the light it receives.
constexpr int kMaxPathVertices = 1024;
// Samples of rho_hd for BxDFs without a closed form (4 x 4 jittered).
constexpr int kRhoSqrtSamples = 4;

// The six well-distributed dimensions of a path's start: light choice, origin (2), direction
// (2) and time, each a radical inverse in its own prime base with digit scrambling drawn from the
// seed.
std::array<Float, 6> pathStart(uint32_t index, uint64_t seed) {
  std::array<Float, 6> u;
  for (int d = 0; d < 6; ++d)
    u[d] = scrambledRadicalInverse(index, kPrimes[d], hashValues({0x76706cULL, seed, uint64_t(d)}));
  return u;
}

void traceOnePath(const Scene& scene, const Distribution1D& lightChoice,
                  const VirtualPointLightOptions& options, uint32_t set, uint32_t path,
                  uint32_t index, MemoryArena& arena, RayStats& stats,
                  std::vector<VirtualPointLight>* out) {
  std::array<Float, 6> u = pathStart(index, options.seed);
  RNG rng(hashValues({0x766c70617468ULL, options.seed, set, path}));
  // A time in the shutter interval, so that moving lights and shapes leave their VPLs where
  // they are during the exposure, not only where they are at its start.
  Float time = lerp(u[5], options.shutterOpen, options.shutterClose);
  std::optional<LightPathStart> start =
      startLightPath(scene, lightChoice, u[0], Point2f(u[1], u[2]), Point2f(u[3], u[4]), time);
  if (!start) return;
  Spectrum alpha = start->beta;
  RayDifferential ray(start->ray);
  const int nonSpecularReflection = kReflection | kDiffuse | kGlossy;
  for (int vertex = 0; vertex < kMaxPathVertices; ++vertex) {
    SurfaceInteraction isect;
    // A vertex is a scattering surface: the interfaces passed on the way are none.
    if (!intersectScattering(scene, &ray, &isect, stats)) break;
    const Primitive& prim = *isect.primitive;
    const BSDF* bsdf = prim.material->getBSDF(isect, arena);
    Vector3f wo = isect.wo;
    if (bsdf->numComponents(nonSpecularReflection) > 0) {
      // The VPL reflects like a Lambertian surface with the hit's rho_hd(wo) (pbrt 2e §15.4)
      // rather than with the hit's own BSDF: keeping every BSDF alive past the preprocess would
      // need its BxDFs and texture values copied out of the arena, and a glossy VPL sends its
      // flux into a narrow lobe whose spikes the bound on G does not limit. The stand-in is exact
      // for matte surfaces and keeps the reflected energy of the others.
      RNG rhoRng(rng.uniformUInt32());
      std::vector<Point2f> uRho = stratifiedSamples2D(kRhoSqrtSamples, rhoRng);
      Spectrum rho = bsdf->rho(wo, uRho, nonSpecularReflection);
      if (!rho.isBlack()) {
        Interaction at(isect.p, faceForward(isect.n, wo), isect.pError, wo, isect.time);
        out->push_back({at, alpha * rho * kInvPi});
      }
    }
    // Continue by sampling the whole BSDF, with Russian roulette on the throughput's change so
    // that the stored points carry similar flux.
    Vector3f wi;
    Float pdf;
    Float uComponent = rng.uniformFloat();
    Point2f uDirection(rng.uniformFloat(), rng.uniformFloat());
    Spectrum f = bsdf->sampleF(wo, &wi, uComponent, uDirection, &pdf, kAllBxDF);
    if (f.isBlack() || pdf == 0) break;
    Spectrum scale = f * (absDot(wi, bsdf->shadingNormal()) / pdf);
    Float continueProb = std::min(Float(1), scale.maxComponent());
    if (!(rng.uniformFloat() < continueProb)) break;
    alpha *= scale / continueProb;
    if (!alpha.isFinite()) break;
    ray = RayDifferential(isect.spawnRay(wi));
  }
}

}  // namespace

size_t VirtualPointLightSets::count() const {
  size_t n = 0;
  for (const auto& s : sets) n += s.size();
  return n;
}

size_t VirtualPointLightSets::memoryBytes() const {
  size_t bytes = sets.capacity() * sizeof(sets[0]);
  for (const auto& s : sets) bytes += s.capacity() * sizeof(VirtualPointLight);
  return bytes;
}

VirtualPointLightSets traceVirtualPointLights(const Scene& scene, int nSets, int pathsPerSet,
                                              const VirtualPointLightOptions& options) {
  VirtualPointLightSets result;
  result.pathsPerSet = pathsPerSet;
  result.sets.resize(size_t(nSets));
  if (scene.lights().empty()) return result;
  std::optional<Distribution1D> lightChoice = lightPowerDistribution(scene);
  if (!lightChoice) return result;
  // One thread, in index order: a few thousand short paths take milliseconds, and the order
  // makes the sets the same on every run.
  MemoryArena arena;
  RayStats stats;
  for (int s = 0; s < nSets; ++s)
    for (int i = 0; i < pathsPerSet; ++i) {
      uint32_t index = uint32_t(s) * uint32_t(pathsPerSet) + uint32_t(i);
      traceOnePath(scene, *lightChoice, options, uint32_t(s), uint32_t(i), index, arena, stats,
                   &result.sets[size_t(s)]);
      arena.reset();
    }
  for (auto& s : result.sets) s.shrink_to_fit();
  return result;
}

}  // namespace candela
