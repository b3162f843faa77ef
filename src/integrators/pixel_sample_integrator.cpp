#include "integrators/pixel_sample_integrator.h"

#include <oneapi/tbb/enumerable_thread_specific.h>
#include <oneapi/tbb/partitioner.h>
#include <oneapi/tbb/task_arena.h>

#include <array>
#include <atomic>
#include <chrono>

#include "accel/embree/embree_device.h"
#include "core/interrupt.h"
#include "core/parallel_for.h"
#include "core/progress.h"
#include "integrators/adaptive_render.h"
#include "integrators/aov_sampler.h"
#include "integrators/progressive_render.h"

namespace candela {

namespace {
struct TileCounters {
  RayStats rays;
  uint64_t samples = 0;
  uint64_t nonFinite = 0;
  std::optional<PixelSampleIndex> firstNonFinite;
};

void keepFirst(std::optional<PixelSampleIndex>& first, const std::optional<PixelSampleIndex>& s) {
  if (s && (!first || *s < *first)) first = s;
}

struct CameraGroup {
  std::array<CameraSample, kCameraRayGroup> cs;
  std::array<RayDifferential, kCameraRayGroup> ray;
  std::array<Float, kCameraRayGroup> weight;
  std::array<Ray, kCameraRayGroup> traced;  // the rays of positive weight, in order
  std::array<SurfaceInteraction, kCameraRayGroup> hits;
  std::array<bool, kCameraRayGroup> hit;
};
}  // namespace

void RenderResult::add(const RenderResult& other) {
  samples += other.samples;
  rays += other.rays;
  nonFiniteSamples += other.nonFiniteSamples;
  tailSeconds += other.tailSeconds;
  keepFirst(firstNonFinite, other.firstNonFinite);
}

PixelSampleIntegrator::SampleLoop PixelSampleIntegrator::sampleLoop(const RenderInputs& in,
                                                                    const Film& film) const {
  SampleLoop loop;
  loop.pixels = film.pixelBounds();
  loop.rayDifferentials = in.scene.needsRayDifferentials();
  return loop;
}

RenderResult PixelSampleIntegrator::renderSamples(const RenderInputs& in, Film& film,
                                                  const RenderOptions& options) {
  SampleLoop loop = sampleLoop(in, film);
  const bool splats = pixelLight() == PixelLight::Splatted;
  if (splats) {
    // A light subpath belongs to a camera sample (pixel, sample index) and may land anywhere on
    // the film. So with a crop window every pixel of the full image still takes its samples, as
    // in the uncropped render (the film keeps only what lands in the crop); a cropped image is
    // then the same bits as that region of the full one, at the cost of the full render's work.
    // The splats' filter weights are normalised over the area camera samples cover, the image
    // and the filter's reach past its edges (film.filterSupportArea): the light-tracing strategy
    // then measures each pixel as the camera strategies do, whose samples reach past the edges
    // too, and their MIS weights sum to one. Normalised over the image alone, an edge pixel's
    // splats weighed more than its own samples (the top row of a caustic scene under a Gaussian
    // filter was 3.3% brighter than path tracing's).
    loop.splats = &film.enableSplats(film.filterSupportArea());
    loop.pixels = Bounds2i(Point2i(0, 0), film.fullResolution());
  }
  RenderResult result = renderPixelSamples(in, film, options, loop);
  if (splats) film.addLightPaths(result.samples);
  return result;
}

ProgressiveResult PixelSampleIntegrator::render(const RenderInputs& in, Film& film,
                                                const ProgressiveOptions& options) {
  const int spp = in.sampler.samplesPerPixel();
  if (options.adaptive.enabled())  // renderJob has checked that pixelLight() is OwnSamples
    return renderAdaptive([&](const RenderOptions& pass) { return renderSamples(in, film, pass); },
                          film, spp, options);
  if (options.afterPass || options.timeBudget > 0)
    return renderProgressive(
        [&](const RenderOptions& pass) { return renderSamples(in, film, pass); }, spp, options);
  ProgressiveResult result;
  result.total = renderSamples(in, film, options.render);
  result.spp = spp;
  result.passes = 1;
  return result;
}

RenderResult PixelSampleIntegrator::renderPixelSamples(const RenderInputs& in, Film& film,
                                                       const RenderOptions& options,
                                                       const SampleLoop& loop) const {
  auto start = std::chrono::steady_clock::now();
  const Scene& scene = in.scene;
  const Camera& camera = in.camera;
  const Sampler& baseSampler = in.sampler;
  SplatBuffer* splats = loop.splats;
  const Bounds2i bounds = loop.pixels;
  const int threads = options.nThreads > 0 ? options.nThreads : tbb::info::default_concurrency();
  // Tiles are taken one at a time by whichever thread is free, so the render ends within a tile's
  // time of the first thread running out of work. Tiles of the given side, halved until every
  // thread has kTilesPerThread to take, keep that tail short on many cores too.
  constexpr int kTilesPerThread = 16;
  const int width = bounds.pMax.x - bounds.pMin.x, height = bounds.pMax.y - bounds.pMin.y;
  int tile = std::max(1, options.tileSize);
  auto tilesOf = [&](int side) {
    return int64_t((width + side - 1) / side) * ((height + side - 1) / side);
  };
  while (tile > 1 && tilesOf(tile) < int64_t(kTilesPerThread) * threads) tile = (tile + 1) / 2;
  const int nx = (width + tile - 1) / tile;
  const int ny = (height + tile - 1) / tile;
  const int spp = baseSampler.samplesPerPixel();
  const int s0 = std::max(0, options.firstSample);
  const int s1 = options.endSample < 0 ? spp : std::min(options.endSample, spp);
  // Adaptive samplers take their extra samples only where the first ones disagree; progressive
  // passes (a partial sample range) take every sample instead.
  const int initial = std::clamp(baseSampler.initialSamplesPerPixel(), 1, spp);
  const bool adaptive = initial < spp && s0 == 0 && s1 == spp;
  // Offset rays one pixel over are too far apart when a pixel gets many samples (pbrt 3e §1.4.3).
  const Float differentialScale =
      std::max(minDifferentialScale(), 1 / std::sqrt(Float(std::max(1, spp))));
  const VolumeIntegrator* volume =
      scene.volume() && volumeRegionLight() != VolumeRegionLight::Integrator ? in.volumeIntegrator
                                                                             : nullptr;
  const bool differentials = loop.rayDifferentials;
  const bool lens = camera.readsLensSample();
  // An integrator that starts from the camera ray's hit gets its camera rays traced a group of a
  // pixel's samples at a time, where the aggregate traces such rays faster together (the volume
  // integrator and adaptive sampling's probe trace their own).
  // Whether the film keeps sample index s (its AOVs too).
  auto filmTakes = [&](int s) {
    return (loop.filmFirstSample < 0 || s >= loop.filmFirstSample) &&
           (loop.filmEndSample < 0 || s < loop.filmEndSample);
  };
  const bool groupCameraRays =
      loop.firstHit && scene.aggregate().tracesCoherentRaysFaster() && !volume && !adaptive;

  ProgressReporter progress(int64_t(nx) * ny, "Rendering",
                            ProgressReporter::modeFor(options.quiet));
  // Each thread's counters, sampler and arena, kept from tile to tile (a sampler's values depend
  // only on what startPixelSample is given, never on what it was asked before).
  struct ThreadState {
    TileCounters counters;
    std::unique_ptr<Sampler> sampler;
    std::unique_ptr<MemoryArena> arena;
    CameraGroup group;
  };
  tbb::enumerable_thread_specific<ThreadState> states([&] {
    return ThreadState{TileCounters(), baseSampler.clone(), std::make_unique<MemoryArena>(), {}};
  });

  std::atomic<double> lastTileStart{0};
  auto renderTile = [&](int tileIndex) {
    double began = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (double seen = lastTileStart.load(); began > seen;)
      if (lastTileStart.compare_exchange_weak(seen, began)) break;
    enableFlushToZero();  // Embree asks for FTZ/DAZ on every tracing thread
    ThreadState& state = states.local();
    TileCounters& c = state.counters;
    Sampler* sampler = state.sampler.get();
    MemoryArena& arena = *state.arena;
    IntegratorContext ctx{*sampler, arena, c.rays, splats, volume};
    int tx = tileIndex % nx, ty = tileIndex / nx;
    int x0 = bounds.pMin.x + tx * tile, y0 = bounds.pMin.y + ty * tile;
    int x1 = std::min(x0 + tile, bounds.pMax.x), y1 = std::min(y0 + tile, bounds.pMax.y);
    // A sample's radiance, checked and added to the film.
    auto addToFilm = [&](const Point2i& pixel, int s, const CameraSample& cs,
                         PixelSampleResult& result, Float alpha) {
      if (!filmTakes(s)) {
        arena.reset();
        return;
      }
      if (!result.L.isFinite()) {
        ++c.nonFinite;
        keepFirst(c.firstNonFinite, PixelSampleIndex{pixel, s});
        result.L = Spectrum(0);
      }
      film.addSample(pixel, result.L, alpha, cs.filterWeight);
      ++c.samples;
      arena.reset();
    };
    auto cameraRay = [&](const CameraSample& cs, RayDifferential* ray) {
      ++c.rays.cameraRays;
      if (!differentials) return camera.generateRay(cs, ray);
      Float weight = camera.generateRayDifferential(cs, ray);
      ray->scaleDifferentials(differentialScale);
      return weight;
    };
    // One sample: traced, added to the film, and reported for adaptive sampling's decision.
    auto takeSample = [&](const Point2i& pixel, int s, bool wantSurface) {
      // A tile of many samples a pixel takes seconds: an interrupt is noticed per sample.
      throwIfInterrupted();
      sampler->startPixelSample(pixel, s);
      CameraSample cs = ctx.halton ? getCameraSample(*ctx.halton, pixel, film.filter(), lens)
                                   : getCameraSample(*sampler, pixel, film.filter(), lens);
      RayDifferential ray;
      Float rayWeight = cameraRay(cs, &ray);
      PixelSampleResult result;
      Float alpha = 0;
      // Before Li, which may shorten the camera ray's tMax.
      if (rayWeight > 0 && (film.aovs() & kAovGeometric) && filmTakes(s))
        film.addAovSample(pixel, sampleAovs(scene, ray, arena, c.rays), cs.filterWeight);
      if (rayWeight > 0 && wantSurface) {
        // The shape-id rule compares surfaces within one pixel only: any stable id will do.
        SurfaceInteraction first;
        Ray probe = ray;
        if (scene.intersect(probe, &first, c.rays))
          result.surfaceId = uint64_t(reinterpret_cast<uintptr_t>(first.primitive));
      }
      if (rayWeight > 0 && !volume) result.L = Li(ray, scene, ctx, &alpha) * rayWeight;
      if (rayWeight > 0 && volume) {
        // The volume between the camera and the first surface (lrt draft §16.7: Scene::L).
        Ray segment = ray;
        SurfaceInteraction hit;
        scene.intersect(segment, &hit, c.rays);
        Spectrum surface = Li(ray, scene, ctx, &alpha);
        Spectrum transmittance;
        Spectrum inVolume = volume->Li(segment, scene, ctx, &transmittance);
        result.L = (transmittance * surface + inVolume) * rayWeight;
      }
      addToFilm(pixel, s, cs, result, alpha);
      return result;
    };
    // Samples [s, e) of a pixel, within one group (below): the group's camera rays traced
    // together, as coherent rays (Embree's packets), then each path of [s, e) from its camera
    // ray's hit. Each sample is started again after the group, past its camera sample's
    // dimensions, so that its values are those takeSample would draw. The whole group is traced
    // even when a sample range takes part of it: a ray's hit may depend on the rays traced with
    // it (ties between surfaces), so the group must not depend on the range.
    auto takeGroup = [&](const Point2i& pixel, int group, int s, int e) {
      CameraGroup& b = state.group;
      const int g0 = group * kCameraRayGroup, n = std::min(spp, g0 + kCameraRayGroup) - g0;
      int traced = 0;
      for (int i = 0; i < n; ++i) {
        sampler->startPixelSample(pixel, g0 + i);
        b.cs[i] = ctx.halton ? getCameraSample(*ctx.halton, pixel, film.filter(), lens)
                             : getCameraSample(*sampler, pixel, film.filter(), lens);
        b.weight[i] = cameraRay(b.cs[i], &b.ray[i]);
        if (b.weight[i] > 0) b.traced[traced++] = b.ray[i];
      }
      scene.intersectCoherent(std::span<const Ray>(b.traced.data(), size_t(traced)), b.hits.data(),
                              b.hit.data(), c.rays);
      for (int i = 0, j = 0; i < n; ++i) {
        const bool weighted = b.weight[i] > 0;
        const int k = weighted ? j++ : -1;  // its place among the traced rays
        if (g0 + i < s || g0 + i >= e) continue;
        throwIfInterrupted();
        PixelSampleResult result;
        Float alpha = 0;
        if (weighted) {
          sampler->startPixelSample(pixel, g0 + i);
          skipCameraSample(*sampler);
          if ((film.aovs() & kAovGeometric) && filmTakes(g0 + i))
            film.addAovSample(pixel, sampleAovs(scene, b.ray[i], arena, c.rays),
                              b.cs[i].filterWeight);
          SurfaceInteraction* hit = b.hit[k] ? &b.hits[k] : nullptr;
          result.L =
              loop.firstHit->LiFromFirstHit(b.ray[i], hit, b.traced[k].tMax, scene, ctx, &alpha) *
              b.weight[i];
        }
        addToFilm(pixel, g0 + i, b.cs[i], result, alpha);
      }
    };
    std::vector<PixelSampleResult> initialResults;
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        Point2i pixel(x, y);
        if (options.pixels && !options.pixels->contains(pixel)) continue;
        if (adaptive) {
          // The first samples decide whether the pixel gets the rest (pbrt-v2's adaptive
          // sampler); both ranges are taken in index order, so the image stays a function of the
          // pixel's own samples.
          initialResults.clear();
          for (int s = 0; s < initial; ++s) initialResults.push_back(takeSample(pixel, s, true));
          if (sampler->needsMoreSamples(initialResults))
            for (int s = initial; s < spp; ++s) takeSample(pixel, s, false);
        } else if (groupCameraRays) {
          for (int s = s0; s < s1;) {
            int group = s / kCameraRayGroup, e = std::min(s1, (group + 1) * kCameraRayGroup);
            takeGroup(pixel, group, s, e);
            s = e;
          }
        } else {
          for (int s = s0; s < s1; ++s) takeSample(pixel, s, false);
        }
      }
    progress.update(1);
  };

  tbb::task_arena taskArena(threads);
  parallelFor(
      taskArena, 0, nx * ny, [&](int i) { renderTile(i); }, tbb::simple_partitioner());
  progress.done();

  RenderResult result;
  for (const ThreadState& state : states) {
    const TileCounters& c = state.counters;
    result.rays += c.rays;
    result.samples += c.samples;
    result.nonFiniteSamples += c.nonFinite;
    keepFirst(result.firstNonFinite, c.firstNonFinite);
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.tailSeconds = std::max(0.0, result.seconds - lastTileStart.load());
  return result;
}

}  // namespace candela
