#include "integrators/irradiance/irradiance_prepass.h"

#include <oneapi/tbb/enumerable_thread_specific.h>
#include <oneapi/tbb/task_arena.h>

#include <atomic>
#include <memory>

#include "cameras/camera.h"
#include "core/parallel_for.h"
#include "core/progress.h"
#include "core/rng.h"
#include "integrators/irradiance/irradiance_interpolation.h"

namespace candela {

namespace {

// The grid points of one round: every step-th pixel in x and y, minus those of the coarser
// grids before it; in row-major order.
std::vector<Point2i> roundPixels(const Point2i& resolution, int step, bool first) {
  std::vector<Point2i> pixels;
  for (int y = 0; y < resolution.y; y += step)
    for (int x = 0; x < resolution.x; x += step)
      if (first || x % (2 * step) != 0 || y % (2 * step) != 0) pixels.emplace_back(x, y);
  return pixels;
}

// A seed for the whole prepass from the scene's sampler (so that --seed changes it): two values
// of a pixel sample no render takes.
uint64_t prepassSeed(const Sampler& sampler) {
  std::unique_ptr<Sampler> s = sampler.clone();
  s->startPixelSample(Point2i(-1, -1), 0);
  uint64_t a = uint64_t(s->get1D() * 0x1p24f), b = uint64_t(s->get1D() * 0x1p24f);
  return hashValues({a, b, 0x1c0ffee});
}

// Grid points per batch: a round is taken in batches of this many, in order, each seeing the
// samples of those before it, so that memory for the found points stays bounded on large images.
// A constant, so batches never depend on threads.
constexpr size_t kBatchPixels = 1 << 16;

struct WorkerCounters {
  RayStats rays;
};

}  // namespace

PrepassResult fillIrradianceCache(IrradianceOctree& cache, const Camera& camera,
                                  const Sampler& sampler, const PrepassPlan& plan,
                                  const FindUncachedPoints& findUncached,
                                  const ComputeCacheSample& compute,
                                  const PrepassOptions& options) {
  PrepassResult result;
  const uint64_t seed = prepassSeed(sampler);
  const int64_t totalPixels = int64_t(plan.resolution.x) * plan.resolution.y;
  ProgressReporter progress(totalPixels, "Irradiance cache",
                            ProgressReporter::modeFor(options.quiet));
  tbb::enumerable_thread_specific<WorkerCounters> counters;
  int threads = options.nThreads > 0 ? options.nThreads : tbb::info::default_concurrency();
  tbb::task_arena arena(threads);
  int firstStep = std::max(1, plan.firstStep);

  // One batch of a round's grid points, [begin, end) in its order; number counts the round's
  // points so far.
  auto runBatch = [&](const std::vector<Point2i>& pixels, size_t begin, size_t end, int round,
                      uint64_t& number) {
    const size_t nPixels = end - begin;
    // 1. Camera rays through the pixel centres (lens centre, mid-shutter), with differentials one
    // pixel apart so that pixel spacings are in pixels of this image.
    std::vector<std::vector<IrradianceQuery>> found(nPixels);
    parallelFor(arena, size_t(0), nPixels, [&](size_t i) {
      if (options.setUpThread) options.setUpThread();
      WorkerCounters& c = counters.local();
      const Point2i& pixel = pixels[begin + i];
      std::unique_ptr<Sampler> s = sampler.clone();
      s->startPixelSample(pixel, 0);
      MemoryArena memory;
      IntegratorContext ctx{*s, memory, c.rays};
      CameraSample cs;
      cs.pFilm = Point2f(Float(pixel.x) + 0.5f, Float(pixel.y) + 0.5f);
      cs.pLens = Point2f(0.5f, 0.5f);
      cs.time = 0.5f;
      RayDifferential ray;
      ++c.rays.cameraRays;
      if (camera.generateRayDifferential(cs, &ray) > 0) findUncached(ray, ctx, &found[i]);
    });

    // 2. Number the points in pixel order; drop those that the kept points before them will
    // cover once inserted. A kept point's radius is at least minPixelSpacing pixels, so a
    // provisional sample of that radius gives a lower bound on its weight anywhere.
    struct Job {
      IrradianceQuery query;
      uint64_t number;
      size_t pixel;
    };
    std::vector<Job> jobs;
    IrradianceOctree provisional(cache.bounds());
    for (size_t i = 0; i < nPixels; ++i)
      for (const IrradianceQuery& q : found[i]) {
        ++result.uncached;
        uint64_t n = number++;
        Float w = interpolateIrradiance(cache, q.at.p, q.n, plan.cosMaxAngle).sumWeight +
                  interpolateIrradiance(provisional, q.at.p, q.n, plan.cosMaxAngle).sumWeight;
        if (w > 0 && w >= plan.minWeight) continue;
        Float radius = plan.minPixelSpacing * q.pixelSpacing;
        if (radius > 0 && radius < kInfinity) provisional.add({q.at.p, q.n, Spectrum(0), radius});
        jobs.push_back({q, n, i});
      }
    found.clear();

    // Progress counts pixels: a pixel is done when its last estimate is.
    std::vector<std::atomic<int>> pending(nPixels);
    for (const Job& j : jobs) pending[j.pixel].fetch_add(1, std::memory_order_relaxed);
    int64_t idle = 0;
    for (size_t i = 0; i < nPixels; ++i)
      if (pending[i].load(std::memory_order_relaxed) == 0) ++idle;
    progress.update(idle);

    // 3. Estimate in parallel, each from its own number; insert in number order.
    std::vector<IrradianceSample> samples(jobs.size());
    parallelFor(arena, size_t(0), jobs.size(), [&](size_t k) {
      if (options.setUpThread) options.setUpThread();
      WorkerCounters& c = counters.local();
      samples[k] =
          compute(jobs[k].query, hashValues({seed, uint64_t(round), jobs[k].number}), c.rays);
      if (pending[jobs[k].pixel].fetch_sub(1) == 1) progress.update(1);
    });
    for (const IrradianceSample& s : samples) cache.add(s);
    result.estimated += samples.size();
  };

  int round = 0;
  for (int step = firstStep; step >= 1; step /= 2, ++round) {
    std::vector<Point2i> pixels = roundPixels(plan.resolution, step, step == firstStep);
    result.cameraRays += pixels.size();
    uint64_t number = 0;
    for (size_t begin = 0; begin < pixels.size(); begin += kBatchPixels)
      runBatch(pixels, begin, std::min(pixels.size(), begin + kBatchPixels), round, number);
  }
  progress.done();
  for (const WorkerCounters& c : counters) result.rays += c.rays;
  return result;
}

}  // namespace candela
