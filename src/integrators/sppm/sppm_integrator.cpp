#include "integrators/sppm/sppm_integrator.h"

#include <oneapi/tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include "accel/embree/embree_device.h"
#include "accel/primitive.h"
#include "cameras/camera.h"
#include "core/parallel_for.h"
#include "core/progress.h"
#include "core/rng.h"
#include "core/sampling.h"
#include "film/film.h"
#include "integrators/sppm/sppm_grid.h"
#include "materials/material.h"
#include "samplers/radical_inverse.h"
#include "transport/light_paths.h"
#include "transport/light_sampling.h"
#include "transport/scattering_surface.h"

namespace candela {

namespace {

// The fraction of an iteration's photons a pixel keeps in its count N (Hachisuka & Jensen 2009
// §4.2, pbrt 3e §16.2.4): the radius shrinks by sqrt((N + αM) / (N + M)).
constexpr double kAlpha = 2.0 / 3.0;
// Photons per block and blocks per batch: deposits are summed after each batch, in block order.
constexpr int64_t kBlockPhotons = 1024;
constexpr int64_t kBlocksPerBatch = 64;
// Low-discrepancy dimensions: camera paths take pixel position (2), time, lens (2); photons take
// light choice, position (2), direction (2), time.
constexpr int kCameraDims = 5;
constexpr int kPhotonDims = 6;
constexpr uint64_t kCameraTag = 0x63616d657261ULL, kPhotonTag = 0x70686f746f6eULL;

// A seed-dependent rotation of one Halton dimension (Cranley and Patterson 1976).
Float rotation(uint64_t seed, uint64_t a, uint64_t b) {
  return Float(mixBits(hashValues({seed, a, b})) >> 40) * 0x1p-24f;
}

Float rotatedHalton(uint64_t index, int dim, Float shift) {
  Float v = radicalInverse(uint32_t(index), kPrimes[dim]) + shift;
  return std::min(v >= 1 ? v - 1 : v, kOneMinusEpsilon);
}

struct VisiblePoint {
  Point3f p;
  Vector3f wo;
  const BSDF* bsdf = nullptr;  // null: the camera path found no non-specular surface
  Spectrum beta;               // camera path throughput up to the point
};

struct PixelState {
  double ld[3] = {0, 0, 0};   // emitted and direct light, summed over iterations
  double tau[3] = {0, 0, 0};  // flux τ gathered so far, for the current radius
  double n = 0;               // photon count N
  double radius = 0;
  uint64_t hits = 0;  // iterations whose camera ray met a surface (the alpha channel)
  VisiblePoint vp;
  double phi[3] = {0, 0, 0};  // this iteration's Φ and M
  uint64_t m = 0;
};

struct Deposit {
  uint32_t pixel;  // index into the pixel states
  Spectrum value;  // photon weight times the visible point's BSDF
};

class SppmIteration {
 public:
  SppmIteration(const Scene& scene, const Camera& camera, const SppmSettings& s,
                std::vector<PixelState>& pixels)
      : scene_(scene),
        camera_(camera),
        s_(s),
        pixels_(pixels),
        lights_(lightPowerDistribution(scene)),
        // A pixel's iterations are its samples: texture footprints shrink as 1/sqrt(iterations),
        // as in pbrt-v3's SPPM (pbrt 3e §16.2.2), not a whole pixel each.
        differentialScale_(1 / std::sqrt(Float(std::max(1, s.iterations)))) {}

  // The camera path of one pixel in iteration k: emission and direct light into ld, and the
  // visible point (pbrt 3e §16.2.2).
  void cameraPath(const Point2i& pixel, int k, PixelState& px, MemoryArena& arena,
                  RayStats& rays) const {
    std::array<Float, kCameraDims> u;
    for (int d = 0; d < kCameraDims; ++d)
      u[d] = rotatedHalton(
          uint64_t(k), d,
          rotation(s_.seed ^ kCameraTag, uint64_t(uint32_t(pixel.x)) << 32 | uint32_t(pixel.y),
                   uint64_t(d)));
    RNG rng(hashValues({s_.seed, kCameraTag, uint64_t(uint32_t(pixel.x)),
                        uint64_t(uint32_t(pixel.y)), uint64_t(k)}));
    CameraSample cs;
    cs.pFilm = Point2f(Float(pixel.x) + u[0], Float(pixel.y) + u[1]);
    cs.time = u[2];
    cs.pLens = Point2f(u[3], u[4]);
    RayDifferential ray;
    Float weight = camera_.generateRayDifferential(cs, &ray);
    ++rays.cameraRays;
    if (weight == 0) return;
    ray.scaleDifferentials(differentialScale_);
    Spectrum beta(weight), ld(0);
    bool specularBounce = false, counted = false;
    for (int depth = 0; depth < s_.maxDepth;) {
      SurfaceInteraction isect;
      bool crossed = false;
      bool hit = intersectScattering(scene_, &ray, &isect, rays,
                                     [&](const SurfaceInteraction&) { crossed = true; });
      if ((hit || crossed) && !counted) ++px.hits;  // once, a material-less interface too
      counted = true;
      bool countEmission = depth == 0 || specularBounce;
      if (!hit) {
        if (countEmission)
          for (const Light* light : scene_.lights()) ld += beta * light->Le(ray);
        break;
      }
      const Primitive& prim = *isect.primitive;
      if (countEmission && prim.areaLight) ld += beta * prim.areaLight->L(isect, -ray.d);
      if (depth == 0) isect.computeDifferentials(ray);
      const BSDF* bsdf = prim.material->getBSDF(isect, arena);
      if (bsdf->numComponents(kAllBxDF & ~kSpecular) > 0) {
        // One light, chosen uniformly (pbrt 2e §15.1); the photons bring the rest.
        const auto& lights = scene_.lights();
        if (!lights.empty()) {
          size_t n = lights.size();
          size_t li = std::min(size_t(rng.uniformFloat() * Float(n)), n - 1);
          Point2f uLight(rng.uniformFloat(), rng.uniformFloat());
          Point2f uScatter(rng.uniformFloat(), rng.uniformFloat());
          Float uComponent = rng.uniformFloat();
          ld +=
              beta * Float(n) *
              estimateDirect(isect, *bsdf, *lights[li], uLight, uScatter, uComponent, scene_, rays);
        }
        px.vp = VisiblePoint{isect.p, isect.wo, bsdf, beta};
        break;
      }
      if (++depth >= s_.maxDepth) break;
      // A purely specular surface: follow it.
      Vector3f wi;
      Float pdf;
      BxDFType type;
      Spectrum f =
          bsdf->sampleF(isect.wo, &wi, rng.uniformFloat(),
                        Point2f(rng.uniformFloat(), rng.uniformFloat()), &pdf, kAllBxDF, &type);
      if (f.isBlack() || pdf == 0) break;
      beta *= f * (absDot(wi, bsdf->shadingNormal()) / pdf);
      if (!beta.isFinite() || beta.isBlack()) break;
      specularBounce = (type & kSpecular) != 0;
      ray = RayDifferential(isect.spawnRay(wi));
    }
    if (!ld.isFinite()) return;
    for (int c = 0; c < 3; ++c) px.ld[c] += double(ld[c]);
  }

  // Photon g (global index k * photons + i) of the render: deposits at every non-specular surface
  // after the first, which the camera pass's direct lighting covers (pbrt 3e §16.2.3).
  void photonPath(uint64_t g, const VisiblePointGrid& grid, std::span<const uint32_t> pointPixel,
                  Float shutterOpen, Float shutterClose,
                  const std::array<Float, kPhotonDims>& shift, MemoryArena& arena,
                  std::vector<Deposit>* out, RayStats& rays) const {
    if (!lights_) return;
    // The Halton index is 32 bits: each further 2^32 photons take another rotation.
    std::array<Float, kPhotonDims> rotated = shift;
    if (uint64_t epoch = g >> 32)
      for (int d = 0; d < kPhotonDims; ++d)
        rotated[d] = rotation(s_.seed ^ epoch, kPhotonTag, uint64_t(d));
    std::array<Float, kPhotonDims> u;
    for (int d = 0; d < kPhotonDims; ++d) u[d] = rotatedHalton(g, d, rotated[d]);
    RNG rng(hashValues({s_.seed, kPhotonTag, g}));
    Float time = shutterOpen + u[5] * (shutterClose - shutterOpen);
    std::optional<LightPathStart> start =
        startLightPath(scene_, *lights_, u[0], Point2f(u[1], u[2]), Point2f(u[3], u[4]), time);
    if (!start) return;
    Spectrum beta = start->beta;
    RayDifferential ray(start->ray);
    for (int depth = 0; depth < s_.maxDepth;) {
      SurfaceInteraction isect;
      if (!intersectScattering(scene_, &ray, &isect, rays)) break;
      const Primitive& prim = *isect.primitive;
      const BSDF* bsdf = prim.material->getBSDF(isect, arena);
      // A photon on a purely specular surface is not on any visible point's surface.
      if (depth > 0 && bsdf->numComponents(kAllBxDF & ~kSpecular) > 0) {
        for (uint32_t j : grid.candidates(isect.p)) {
          uint32_t pi = pointPixel[j];
          const PixelState& px = pixels_[pi];
          double r = px.radius;
          Vector3f d = px.vp.p - isect.p;
          if (double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z > r * r) continue;
          out->push_back(Deposit{pi, beta * px.vp.bsdf->f(px.vp.wo, isect.wo)});
        }
      }
      if (++depth >= s_.maxDepth) break;
      Vector3f wi;
      Float pdf;
      BxDFType type;
      Spectrum f =
          bsdf->sampleF(isect.wo, &wi, rng.uniformFloat(),
                        Point2f(rng.uniformFloat(), rng.uniformFloat()), &pdf, kAllBxDF, &type);
      if (f.isBlack() || pdf == 0) break;
      Spectrum next = beta * f * (absDot(wi, bsdf->shadingNormal()) / pdf);
      // Particles carry power, not radiance: undo the (eta_o / eta_i)^2 radiance scaling of
      // refraction (Veach 1997 §5.2, the adjoint BSDF).
      if ((type & kTransmission) && bsdf->eta != 1) {
        Float e2 = bsdf->eta * bsdf->eta;
        next *= dot(isect.wo, bsdf->shadingNormal()) > 0 ? e2 : 1 / e2;
      }
      // Russian roulette that keeps the photon's luminance (pbrt 3e §16.2.3).
      Float y = beta.y();
      if (!(y > 0)) break;
      Float continueProb = std::min(Float(1), next.y() / y);
      if (!(continueProb > 0) || rng.uniformFloat() >= continueProb) break;
      beta = next / continueProb;
      if (!beta.isFinite()) break;
      ray = RayDifferential(isect.spawnRay(wi));
    }
  }

 private:
  const Scene& scene_;
  const Camera& camera_;
  const SppmSettings& s_;
  std::vector<PixelState>& pixels_;
  std::optional<Distribution1D> lights_;  // none when no light emits
  Float differentialScale_;
};

}  // namespace

ProgressiveResult SppmIntegrator::render(const RenderInputs& in, Film& film,
                                         const ProgressiveOptions& options) {
  const Scene& scene = in.scene;
  const Camera& camera = in.camera;
  auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  const Bounds2i bounds = film.pixelBounds();
  const int width = std::max(0, bounds.pMax.x - bounds.pMin.x);
  const int height = std::max(0, bounds.pMax.y - bounds.pMin.y);
  const Point2i full = film.fullResolution();
  // Photons per iteration follow the full image, not the crop, so that a crop traces the same
  // photons as the full render.
  const int64_t photons = settings_.photonsPerIteration > 0 ? settings_.photonsPerIteration
                                                            : int64_t(full.x) * int64_t(full.y);
  std::vector<PixelState> pixels(size_t(width) * size_t(height));
  for (PixelState& px : pixels) px.radius = settings_.initialRadius;
  SppmIteration iteration(scene, camera, settings_, pixels);

  std::array<Float, kPhotonDims> shift;
  for (int d = 0; d < kPhotonDims; ++d)
    shift[d] = rotation(settings_.seed, kPhotonTag, uint64_t(d));
  const Float shutterOpen = camera.shutterOpen(), shutterClose = camera.shutterClose();

  int threads =
      options.render.nThreads > 0 ? options.render.nThreads : tbb::info::default_concurrency();
  tbb::task_arena arena(threads);
  std::vector<MemoryArena> rowArenas(static_cast<size_t>(height));
  std::vector<RayStats> rowRays(static_cast<size_t>(height));
  SppmStats stats;
  ProgressiveResult result;
  ProgressReporter progress(settings_.iterations, "SPPM",
                            ProgressReporter::modeFor(options.render.quiet));

  auto writeFilm = [&](int done) {
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const PixelState& px = pixels[size_t(y) * width + x];
        double area = double(done) * double(photons) * double(kPi) * px.radius * px.radius;
        Spectrum L;
        for (int c = 0; c < 3; ++c) L[c] = Float(px.ld[c] / done + px.tau[c] / area);
        film.setPixel(Point2i(bounds.pMin.x + x, bounds.pMin.y + y), L,
                      Float(double(px.hits) / done));
      }
  };

  int done = 0;
  bool reported = true;
  auto report = [&]() {
    writeFilm(done);
    result.total.seconds = elapsed();
    if (!options.render.quiet)
      std::fprintf(stderr, "SPPM: %d iterations after %.2fs\n", done, result.total.seconds);
    PassReport pr{result.passes, done, result.total.seconds, result.total};
    ++result.passes;
    reported = true;
    return options.afterPass ? options.afterPass(pr) : true;
  };

  for (int k = 0; k < settings_.iterations; ++k) {
    if (options.timeBudget > 0 && k > 0) {
      // Every iteration costs about the same: the next takes the mean so far.
      double e = elapsed();
      if (e + e / k > options.timeBudget) {
        result.reason = StopReason::TimeBudget;
        break;
      }
    }
    // Camera pass: one path per pixel, rows in parallel (a row's arena holds its BSDFs until the
    // photons have been gathered).
    parallelFor(arena, 0, height, [&](int y) {
      enableFlushToZero();  // Embree asks for FTZ/DAZ on every tracing thread
      rowArenas[y].reset();
      for (int x = 0; x < width; ++x)
        iteration.cameraPath(Point2i(bounds.pMin.x + x, bounds.pMin.y + y), k,
                             pixels[size_t(y) * width + x], rowArenas[y], rowRays[y]);
    });
    std::vector<GridPoint> points;
    std::vector<uint32_t> pointPixel;
    for (size_t i = 0; i < pixels.size(); ++i) {
      const PixelState& px = pixels[i];
      if (!px.vp.bsdf || px.vp.beta.isBlack()) continue;
      points.push_back(GridPoint{px.vp.p, Float(px.radius)});
      pointPixel.push_back(uint32_t(i));
    }
    VisiblePointGrid grid(points, 4 * points.size() + 64);
    stats.visiblePoints += points.size();
    stats.maxGridBytes = std::max(stats.maxGridBytes, grid.memoryBytes());

    // Photon pass, in batches of fixed blocks; deposits are summed in photon order.
    const int64_t nBlocks = (photons + kBlockPhotons - 1) / kBlockPhotons;
    for (int64_t b0 = 0; b0 < nBlocks; b0 += kBlocksPerBatch) {
      int64_t b1 = std::min(nBlocks, b0 + kBlocksPerBatch);
      std::vector<std::vector<Deposit>> deposits(size_t(b1 - b0));
      std::vector<RayStats> blockRays(size_t(b1 - b0));
      parallelFor(arena, b0, b1, [&](int64_t b) {
        enableFlushToZero();
        MemoryArena mem;
        int64_t end = std::min(photons, (b + 1) * kBlockPhotons);
        for (int64_t i = b * kBlockPhotons; i < end; ++i) {
          iteration.photonPath(uint64_t(k) * uint64_t(photons) + uint64_t(i), grid, pointPixel,
                               shutterOpen, shutterClose, shift, mem, &deposits[b - b0],
                               blockRays[b - b0]);
          mem.reset();
        }
      });
      for (size_t b = 0; b < deposits.size(); ++b) {
        for (const Deposit& d : deposits[b]) {
          PixelState& px = pixels[d.pixel];
          for (int c = 0; c < 3; ++c) px.phi[c] += double(d.value[c]);
          ++px.m;
        }
        result.total.rays += blockRays[b];
      }
    }
    stats.photonsShot += uint64_t(photons);

    // Progressive radiance estimate update (Hachisuka & Jensen 2009 eq. 6-10; pbrt 3e §16.2.4).
    parallelFor(arena, size_t(0), pixels.size(), [&](size_t i) {
      PixelState& px = pixels[i];
      if (px.m > 0) {
        double nNew = px.n + kAlpha * double(px.m);
        double rNew = px.radius * std::sqrt(nNew / (px.n + double(px.m)));
        double shrink = (rNew * rNew) / (px.radius * px.radius);
        for (int c = 0; c < 3; ++c)
          px.tau[c] = (px.tau[c] + double(px.vp.beta[c]) * px.phi[c]) * shrink;
        px.n = nNew;
        px.radius = rNew;
      }
      for (double& v : px.phi) v = 0;
      px.m = 0;
      px.vp = VisiblePoint{};
    });
    for (int y = 0; y < height; ++y) {
      result.total.rays += rowRays[y];
      rowRays[y] = RayStats{};
    }
    result.total.samples += uint64_t(pixels.size());
    done = k + 1;
    result.spp = done;
    stats.iterations = done;
    reported = false;
    progress.update(1);
    bool last = done == settings_.iterations;
    if ((done & (done - 1)) == 0 || last) {
      if (!report()) {
        if (!last) result.reason = StopReason::TargetError;
        break;
      }
    }
  }
  progress.done();
  if (!reported && done > 0) report();
  result.total.seconds = elapsed();
  {
    std::lock_guard<std::mutex> lock(statsMutex_);
    stats_ = stats;
  }
  return result;
}

std::string SppmIntegrator::statsReport() const {
  std::lock_guard<std::mutex> lock(statsMutex_);
  std::ostringstream os;
  os << "  sppm iterations  " << stats_.iterations << "\n";
  os << "  sppm photons shot  " << stats_.photonsShot << "\n";
  os << "  sppm visible points (all iterations)  " << stats_.visiblePoints << "\n";
  os << "  sppm grid memory (largest)  " << stats_.maxGridBytes << " bytes\n";
  return os.str();
}

}  // namespace candela
