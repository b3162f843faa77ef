#include "transport/photon_shooting.h"

#include <oneapi/tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <limits>

#include "accel/primitive.h"
#include "core/parallel_for.h"
#include "core/progress.h"
#include "core/rng.h"
#include "core/sampling.h"
#include "materials/material.h"
#include "samplers/radical_inverse.h"
#include "transport/light_paths.h"
#include "transport/scattering_surface.h"
#include "transport/specular_differentials.h"

namespace candela {

namespace {

// Paths per block (pbrt-v2 merges its tasks' photons every 4096 paths), and the most blocks per
// parallel batch; batches start at one block and double, so that small maps shoot few paths.
constexpr uint64_t kBlockPaths = 4096;
constexpr uint64_t kMaxBlocksPerBatch = 16;
// pbrt-v2's give-up rule: past 500,000 paths, a map still storing fewer than one photon per 1024
// paths is not going to fill in reasonable time.
constexpr uint64_t kGiveUpAfterPaths = 500000;
constexpr uint64_t kGiveUpPathsPerPhoton = 1024;
constexpr Float kRadiancePhotonFraction = 0.125f;  // pbrt 2e §15.6.3
// Low-discrepancy dimensions per path: light choice, position (2), direction (2), first bounce (3),
// time.
constexpr int kQuasiRandomDims = 9;
constexpr int kRhoSamples = 16;

const char* kindName(int kind) {
  static const char* names[kPhotonKinds] = {"direct", "caustic", "indirect"};
  return names[kind];
}

struct BlockResult {
  std::vector<Photon> photons[kPhotonKinds];
  std::vector<uint64_t> paths[kPhotonKinds];  // the path index of each photon
  std::vector<RadiancePhotonSite> sites;
  RayStats rays;
};

// What one batch may deposit, fixed before the batch starts so that it does not depend on which
// block finishes first.
struct Accepting {
  bool kind[kPhotonKinds] = {false, false, false};
  bool any() const { return kind[0] || kind[1] || kind[2]; }
};

class PhotonTracer {
 public:
  PhotonTracer(const Scene& scene, const PhotonShootingPlan& plan, const Distribution1D& lights,
               std::span<const Point2f> rhoU1, std::span<const Point2f> rhoU2)
      : scene_(scene), plan_(plan), lights_(lights), rhoU1_(rhoU1), rhoU2_(rhoU2) {
    // The Halton points are rotated by a seed-dependent shift per dimension (Cranley and
    // Patterson 1976): still low-discrepancy, a different set per seed, and far cheaper per path
    // than digit scrambling.
    for (int d = 0; d < kQuasiRandomDims; ++d)
      shift_[d] =
          Float(mixBits(hashValues({plan.seed, uint64_t(d), 0x70686f746f6eULL})) >> 40) * 0x1p-24f;
  }

  void trace(uint64_t index, const Accepting& accepting, MemoryArena& arena, BlockResult* out,
             RayStats& stats) const {
    std::array<Float, kQuasiRandomDims> u;
    for (int d = 0; d < kQuasiRandomDims; ++d) {
      Float v = radicalInverse(uint32_t(index), kPrimes[d]) + shift_[d];
      u[d] = std::min(v >= 1 ? v - 1 : v, kOneMinusEpsilon);
    }
    RNG rng(hashValues({plan_.seed, index}));

    Float time = plan_.shutterOpen + u[8] * (plan_.shutterClose - plan_.shutterOpen);
    std::optional<LightPathStart> start =
        startLightPath(scene_, lights_, u[0], Point2f(u[1], u[2]), Point2f(u[3], u[4]), time);
    if (!start) return;
    Spectrum alpha = start->beta;
    RayDifferential ray(start->ray);
    bool specularPath = true;
    for (int nIntersections = 0;;) {
      SurfaceInteraction isect;
      if (!intersectScattering(scene_, &ray, &isect, stats)) break;
      const Primitive& prim = *isect.primitive;
      ++nIntersections;
      const BSDF* bsdf = prim.material->getBSDF(isect, arena);
      if (bsdf->numComponents(kAllBxDF & ~kSpecular) > 0) {
        int kind = nIntersections == 1 ? int(PhotonKind::Direct)
                   : specularPath      ? int(PhotonKind::Caustic)
                                       : int(PhotonKind::Indirect);
        if (accepting.kind[kind]) {
          out->photons[kind].push_back(Photon{isect.p, alpha, isect.wo});
          out->paths[kind].push_back(index);
          if (plan_.radianceSites && rng.uniformFloat() < kRadiancePhotonFraction) {
            RadiancePhotonSite site;
            site.p = isect.p;
            site.n = faceForward(isect.n, isect.wo);
            site.rhoR = bsdf->rho(rhoU1_, rhoU2_, kAllReflection);
            site.rhoT = bsdf->rho(rhoU1_, rhoU2_, kAllTransmission);
            out->sites.push_back(site);
          }
        }
      }
      if (nIntersections >= plan_.maxPhotonDepth) break;

      // Scatter: the first bounce takes low-discrepancy numbers, later ones pseudo-random ones.
      bool first = nIntersections == 1;
      Float uc = first ? u[5] : rng.uniformFloat();
      Point2f u2 = first ? Point2f(u[6], u[7]) : Point2f(rng.uniformFloat(), rng.uniformFloat());
      Vector3f wi;
      Float pdf;
      BxDFType type;
      Spectrum f = bsdf->sampleF(isect.wo, &wi, uc, u2, &pdf, kAllBxDF, &type);
      if (f.isBlack() || pdf == 0) break;
      Spectrum next = alpha * f * (absDot(wi, bsdf->shadingNormal()) / pdf);
      // Refraction scales radiance by (eta_o / eta_i)^2 but not the power particles carry: a
      // photon uses the adjoint BSDF, without that factor (Veach 1997 §5.2; pbrt 2e's photon
      // shooting keeps it, which is harmless only when the path leaves the dielectric again).
      if ((type & kTransmission) && bsdf->eta != 1) {
        Float e2 = bsdf->eta * bsdf->eta;
        next *= dot(isect.wo, bsdf->shadingNormal()) > 0 ? e2 : 1 / e2;
      }
      // Russian roulette that keeps the photon's luminance (pbrt 2e §15.6.1): equal-weight photons
      // give the density estimates the least variance.
      Float continueProb = std::min(Float(1), next.y() / alpha.y());
      if (!(continueProb > 0) || rng.uniformFloat() >= continueProb) break;
      alpha = next / continueProb;
      if (!alpha.isFinite()) break;
      specularPath = specularPath && (type & kSpecular) != 0;
      // Past the first surface a path can only add caustic photons while it stays specular, and
      // indirect ones: once the maps it could still add to are full, it is done.
      bool caustic = specularPath && accepting.kind[int(PhotonKind::Caustic)];
      if (!caustic && !accepting.kind[int(PhotonKind::Indirect)]) break;
      ray = RayDifferential(isect.spawnRay(wi));
    }
    arena.reset();
  }

 private:
  const Scene& scene_;
  const PhotonShootingPlan& plan_;
  const Distribution1D& lights_;
  std::span<const Point2f> rhoU1_, rhoU2_;
  std::array<Float, kQuasiRandomDims> shift_;
};

// A map being filled: photons in path order until it has what it wants.
struct MapFill {
  int64_t wanted = 0;
  bool done = true;
  ShotPhotons shot;
};

}  // namespace

PhotonShootingResult shootPhotons(const Scene& scene, const PhotonShootingPlan& plan) {
  PhotonShootingResult result;
  std::optional<Distribution1D> lightChoice = lightPowerDistribution(scene);
  if (!lightChoice) return result;
  const Distribution1D& lights = *lightChoice;

  const int d = int(PhotonKind::Direct), c = int(PhotonKind::Caustic),
            in = int(PhotonKind::Indirect);
  MapFill fills[kPhotonKinds];
  for (int k = 0; k < kPhotonKinds; ++k) {
    fills[k].wanted = plan.wanted[k];
    fills[k].done = plan.wanted[k] <= 0;
  }
  if (plan.directFollowsIndirect) {
    fills[d].wanted = std::numeric_limits<int64_t>::max();
    fills[d].done = fills[in].done;
  }

  // Hammersley points for the radiance photons' reflectances (exact for Lambertian surfaces).
  std::vector<Point2f> rhoU1, rhoU2;
  for (int i = 0; i < kRhoSamples; ++i) {
    rhoU1.emplace_back((i + Float(0.5)) / kRhoSamples, radicalInverse(uint32_t(i), 2));
    rhoU2.emplace_back(radicalInverse(uint32_t(i), 3), radicalInverse(uint32_t(i), 5));
  }
  PhotonTracer tracer(scene, plan, lights, rhoU1, rhoU2);

  int64_t progressTotal = 0;
  for (int k = 0; k < kPhotonKinds; ++k)
    if (!fills[k].done && !(k == d && plan.directFollowsIndirect)) progressTotal += fills[k].wanted;
  ProgressReporter progress(progressTotal, "Shooting photons",
                            ProgressReporter::modeFor(!plan.showProgress));
  int threads = plan.nThreads > 0 ? plan.nThreads : tbb::info::default_concurrency();
  tbb::task_arena arena(threads);

  constexpr uint64_t kMaxPaths = std::numeric_limits<uint32_t>::max();
  uint64_t shot = 0;
  auto anyOpen = [&] { return !fills[0].done || !fills[1].done || !fills[2].done; };
  for (uint64_t batchBlocks = 1; anyOpen();
       batchBlocks = std::min(kMaxBlocksPerBatch, 2 * batchBlocks)) {
    Accepting accepting;
    for (int k = 0; k < kPhotonKinds; ++k) accepting.kind[k] = !fills[k].done;
    uint64_t blocks = std::min(batchBlocks, (kMaxPaths - shot) / kBlockPaths);
    std::vector<BlockResult> results(blocks);
    parallelFor(arena, uint64_t(0), blocks, [&](uint64_t b) {
      MemoryArena mem;
      uint64_t first = shot + b * kBlockPaths;
      for (uint64_t i = first; i < first + kBlockPaths; ++i)
        tracer.trace(i, accepting, mem, &results[b], results[b].rays);
    });
    // Concatenate in block order; a map that fills takes the photons of paths up to the one that
    // filled it, and divides by the number of paths up to that one.
    int64_t stored = 0;
    auto full = [&](int k) { return int64_t(fills[k].shot.photons.size()) >= fills[k].wanted; };
    for (const BlockResult& r : results) {
      for (int k : {c, in, d}) {
        MapFill& f = fills[k];
        if (f.done) continue;
        bool follows = k == d && plan.directFollowsIndirect;
        for (size_t j = 0; j < r.photons[k].size(); ++j) {
          uint64_t path = r.paths[k][j];
          if (follows ? (full(in) && path >= fills[in].shot.nPaths)
                      : (full(k) && path >= f.shot.nPaths))
            break;
          f.shot.photons.push_back(r.photons[k][j]);
          f.shot.nPaths = path + 1;
          if (!follows) ++stored;
        }
      }
      result.radianceSites.insert(result.radianceSites.end(), r.sites.begin(), r.sites.end());
      result.rays += r.rays;
    }
    shot += blocks * kBlockPaths;
    for (int k : {c, in, d}) {
      MapFill& f = fills[k];
      if (f.done) continue;
      bool follows = k == d && plan.directFollowsIndirect;
      if (follows ? fills[in].done : full(k)) {
        f.done = true;
        if (follows) f.shot.nPaths = fills[in].shot.nPaths;
      } else {
        f.shot.nPaths = shot;  // an open map has seen every path shot so far
      }
    }
    progress.update(stored);
    bool giveUpTime = shot > kGiveUpAfterPaths;
    for (int k = 0; k < kPhotonKinds; ++k) {
      MapFill& f = fills[k];
      // Direct photons that follow the indirect ones end with them.
      if (f.done || (k == d && plan.directFollowsIndirect)) continue;
      if ((giveUpTime && uint64_t(f.shot.photons.size()) < shot / kGiveUpPathsPerPhoton) ||
          shot + kBlockPaths > kMaxPaths) {
        f.done = true;
        if (plan.warn)
          plan.warn(std::string("the ")
                        .append(kindName(k))
                        .append(" photon map stored only ")
                        .append(std::to_string(f.shot.photons.size()))
                        .append(" photons in ")
                        .append(std::to_string(shot))
                        .append(" paths (fewer than one per ")
                        .append(std::to_string(kGiveUpPathsPerPhoton))
                        .append("); giving up short of the ")
                        .append(std::to_string(f.wanted))
                        .append(" wanted")
                        .append(f.shot.photons.empty() ? ": the map is left out" : ""));
        if (k == in && plan.directFollowsIndirect) fills[d].done = true;
      }
    }
  }
  progress.done();
  for (int k = 0; k < kPhotonKinds; ++k) result.maps[k] = std::move(fills[k].shot);
  result.pathsShot = shot;
  return result;
}

}  // namespace candela
