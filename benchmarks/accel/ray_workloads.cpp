#include "ray_workloads.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <ctime>

#include "accel/embree/embree_device.h"
#include "core/rng.h"
#include "core/sampling.h"

namespace candela::bench {

RaySets makeRays(const BenchScene& scene, const Aggregate& reference, long nCamera, uint64_t seed) {
  RaySets sets;
  enableFlushToZero();
  RNG rng(seed);
  double aspect = double(scene.resolution.x) / scene.resolution.y;
  int nx = std::max(1, int(std::lround(std::sqrt(nCamera * aspect))));
  int ny = std::max(1, int(std::lround(double(nCamera) / nx)));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      CameraSample cs;
      cs.pFilm =
          Point2f((i + 0.5f) * scene.resolution.x / nx, (j + 0.5f) * scene.resolution.y / ny);
      Float u0 = rng.uniformFloat();
      cs.pLens = Point2f(u0, rng.uniformFloat());
      cs.time = rng.uniformFloat();
      Ray ray;
      if (scene.camera->generateRay(cs, &ray) == 0) continue;
      sets.camera.push_back(ray);
      Ray r = ray;
      SurfaceInteraction si;
      if (!reference.intersect(r, &si)) continue;
      // A diffuse bounce on the side the camera sees.
      Normal3f n = faceForward(si.n, si.wo);
      Vector3f nv = normalize(Vector3f(n)), s, t;
      coordinateSystem(nv, &s, &t);
      Float u1 = rng.uniformFloat();
      Vector3f local = sampleCosineHemisphere(Point2f(u1, rng.uniformFloat()));
      Vector3f wi = s * local.x + t * local.y + nv * local.z;
      Ray bounce = si.spawnRay(wi);
      bounce.time = ray.time;
      sets.bounce.push_back(bounce);
      Ray shadow = si.spawnRayTo(scene.lightPosition);
      shadow.time = ray.time;
      sets.shadow.push_back(shadow);
    }
  return sets;
}

namespace {

double threadCpuSeconds() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

long traceRange(const Aggregate& aggregate, const std::vector<Ray>& rays, size_t begin, size_t end,
                bool anyHit) {
  long hits = 0;
  for (size_t i = begin; i != end; ++i) {
    Ray r = rays[i];  // intersect shortens tMax
    if (anyHit) {
      hits += aggregate.intersectP(r);
    } else {
      SurfaceInteraction si;
      hits += aggregate.intersect(r, &si);
    }
  }
  return hits;
}

}  // namespace

TraceResult trace(const Aggregate& aggregate, const std::vector<Ray>& rays, bool anyHit,
                  int threads, int repeats) {
  TraceResult best;
  tbb::task_arena arena(threads);
  for (int rep = 0; rep < std::max(1, repeats); ++rep) {
    TraceResult r;
    if (threads == 1) {
      // On the calling thread, timed by its CPU clock: other processes on the machine do not
      // count.
      enableFlushToZero();
      double start = threadCpuSeconds();
      r.hits = traceRange(aggregate, rays, 0, rays.size(), anyHit);
      r.seconds = threadCpuSeconds() - start;
    } else {
      std::atomic<long> hits{0};
      auto start = std::chrono::steady_clock::now();
      arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), 256),
                          [&](const tbb::blocked_range<size_t>& range) {
                            enableFlushToZero();
                            hits += traceRange(aggregate, rays, range.begin(), range.end(), anyHit);
                          });
      });
      r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      r.hits = hits.load();
    }
    if (rep == 0 || r.seconds < best.seconds) best = r;
  }
  return best;
}

}  // namespace candela::bench
