#include "integrators/metropolis/metropolis_chains.h"

#include <oneapi/tbb/enumerable_thread_specific.h>
#include <oneapi/tbb/task_arena.h>

#include <chrono>
#include <cmath>

#include "accel/embree/embree_device.h"
#include "core/interrupt.h"
#include "core/parallel_for.h"
#include "core/progress.h"
#include "core/sampling.h"
#include "film/splat_buffer.h"
#include "integrators/metropolis/primary_samples.h"

namespace candela {

namespace {

// Distinct purposes of the seed's hashes.
enum : uint64_t { kStartState = 1, kStartStateSeed, kChainPick, kChainSequence, kChainSeed };

struct ThreadState {
  MemoryArena arena;
  RayStats rays;
  MetropolisStats stats;
  uint64_t nonFinite = 0;
};

struct PathSample {
  Spectrum L;
  Point2f pRaster;
  Float y = 0;  // the luminance the chain samples in proportion to
};

class PathEvaluator {
 public:
  // filmArea: where film points are drawn (raster space); imagePixels: the full image's size.
  PathEvaluator(const MetropolisSettings& settings, const BdptIntegrator& paths, const Scene& scene,
                const Camera& camera, const Bounds2f& filmArea, double imagePixels)
      : settings_(settings),
        paths_(paths),
        scene_(scene),
        camera_(camera),
        filmArea_(filmArea),
        areaOverImage_(Float(double(filmArea.pMax.x - filmArea.pMin.x) *
                             double(filmArea.pMax.y - filmArea.pMin.y) / imagePixels)),
        differentialScale_(1 / std::sqrt(Float(std::max<int64_t>(1, settings.mutationsPerPixel)))) {
  }

  // The path of `depth` scattering events that the chain state's numbers make (pbrt 3e
  // §16.4.4): the camera stream gives the film position, time and lens point, the connection
  // stream the strategy.
  PathSample evaluate(PrimarySamples& state, int depth, ThreadState& ts) const {
    PrimarySampleStream cameraStream(state, 0), lightStream(state, 1), connection(state, 2);
    PathSample r;
    Point2f u = cameraStream.get2D();
    CameraSample cs;
    cs.pFilm = Point2f(lerp(u.x, filmArea_.pMin.x, filmArea_.pMax.x),
                       lerp(u.y, filmArea_.pMin.y, filmArea_.pMax.y));
    cs.time = cameraStream.get1D();
    cs.pLens = cameraStream.get2D();
    r.pRaster = cs.pFilm;
    RayDifferential ray;
    Float rayWeight = camera_.generateRayDifferential(cs, &ray);
    ray.scaleDifferentials(differentialScale_);
    ++ts.rays.cameraRays;
    if (rayWeight <= 0) return r;
    int s = 0;
    Float strategies = 1;
    BdptIntegrator::Weighting weighting = BdptIntegrator::Weighting::Unidirectional;
    if (settings_.bidirectional) {
      // One of the depth + 2 strategies, chosen uniformly: its MIS-weighted contribution over
      // the probability of choosing it.
      int n = depth + 2;
      s = std::min(int(connection.get1D() * Float(n)), n - 1);
      strategies = Float(n);
      weighting = BdptIntegrator::Weighting::Mis;
    }
    BdptIntegrator::PathSamplers samplers{cameraStream, lightStream, connection};
    Point2f pElsewhere;
    bool elsewhere = false;
    Spectrum L =
        paths_.fixedLengthContribution(ray, depth, s, weighting, settings_.excludeDirect, scene_,
                                       samplers, ts.arena, ts.rays, &pElsewhere, &elsewhere);
    ts.arena.reset();
    L *= rayWeight * strategies;
    if (!L.isFinite()) {
      ++ts.nonFinite;
      return r;
    }
    // A path through the film point carries the area film points are drawn from over the
    // image's (Film's splat scale counts image pixels). Light reaching the lens (t = 1) does not
    // depend on the film point, and lands in the image: it keeps its value.
    if (elsewhere)
      r.pRaster = pElsewhere;
    else
      L *= areaOverImage_;
    r.L = L;
    r.y = std::max(Float(0), L.y());
    return r;
  }

 private:
  const MetropolisSettings& settings_;
  const BdptIntegrator& paths_;
  const Scene& scene_;
  const Camera& camera_;
  Bounds2f filmArea_;
  Float areaOverImage_;
  Float differentialScale_;
};

PrimarySamples startState(const MetropolisSettings& settings, uint64_t seed, uint64_t index) {
  PrimarySamples state(hashValues({seed, kStartState, index}),
                       hashValues({seed, kStartStateSeed, index}), settings.sigma,
                       settings.largeStepProbability, settings.smallStep);
  state.startLargeStep();
  return state;
}

}  // namespace

RenderResult runMetropolisChains(const MetropolisSettings& settings, const BdptIntegrator& paths,
                                 const Scene& scene, const Camera& camera, Film& film,
                                 uint64_t seed, const RenderOptions& options,
                                 MetropolisStats* stats) {
  auto start = std::chrono::steady_clock::now();
  const Point2i resolution = film.fullResolution();
  const int depths = settings.maxDepth + 1;
  // Film points are drawn over every pixel filter's support, beyond the image by the radius, so
  // that the edge pixels gather splats from all sides as their own samples would (drawn over the
  // image only, the corners of a 16 x 16 render with a Gaussian filter came out 8% dark).
  const Bounds2f filmArea = film.filterSupportArea();
  PathEvaluator evaluator(settings, paths, scene, camera, filmArea,
                          double(resolution.x) * double(resolution.y));
  tbb::enumerable_thread_specific<ThreadState> threadStates;
  int threads = options.nThreads > 0 ? options.nThreads : tbb::info::default_concurrency();
  tbb::task_arena taskArena(threads);

  // Bootstrap: sample k is the k-th start state at depth k mod depths; its luminance is its
  // weight. b is the mean over the bootstrap samples of their luminance summed over depths.
  const int64_t nBootstrap = settings.bootstrapSamples * depths;
  std::vector<Float> weights(size_t(std::max<int64_t>(nBootstrap, 0)));
  {
    ProgressReporter progress(nBootstrap, "Bootstrapping",
                              ProgressReporter::modeFor(options.quiet));
    parallelFor(taskArena, int64_t(0), nBootstrap, [&](int64_t k) {
      enableFlushToZero();
      ThreadState& ts = threadStates.local();
      PrimarySamples state = startState(settings, seed, uint64_t(k));
      weights[size_t(k)] = evaluator.evaluate(state, int(k % depths), ts).y;
      progress.update(1);
    });
  }
  double sum = 0;
  for (Float w : weights) sum += w;
  const double b = settings.bootstrapSamples > 0 ? sum / double(settings.bootstrapSamples) : 0;
  if (stats) stats->b = b;

  SplatBuffer& splats = film.enableSplats(filmArea);
  const int64_t nPixels = int64_t(resolution.x) * resolution.y;
  const int64_t totalMutations = settings.mutationsPerPixel * nPixels;
  // splatScale is then 1 / mutationsPerPixel.
  film.addLightPaths(uint64_t(totalMutations));
  if (b > 0 && settings.chains > 0 && totalMutations > 0) {
    Distribution1D startDistribution(weights);
    const int chains = settings.chains;
    ProgressReporter progress(chains, "Rendering", ProgressReporter::modeFor(options.quiet));
    auto runChain = [&](int c) {
      enableFlushToZero();
      ThreadState& ts = threadStates.local();
      int64_t mutations = totalMutations / chains + (int64_t(c) < totalMutations % chains ? 1 : 0);
      RNG pick(hashValues({seed, kChainPick, uint64_t(c)}));
      int k = startDistribution.sampleDiscrete(pick.uniformFloat());
      int depth = k % depths;
      // The start state is the bootstrap's sample k, made again; then the chain's own numbers.
      PrimarySamples state = startState(settings, seed, uint64_t(k));
      PathSample current = evaluator.evaluate(state, depth, ts);
      state.accept();
      state.reseed(hashValues({seed, kChainSequence, uint64_t(c)}),
                   hashValues({seed, kChainSeed, uint64_t(c)}));
      auto splat = [&](const PathSample& p, Float weight) {
        if (weight > 0 && p.y > 0) splats.add(p.pRaster, p.L * Float(b * weight / p.y));
      };
      int64_t rejects = 0;
      for (int64_t m = 0; m < mutations; ++m) {
        if ((m & 1023) == 0) throwIfInterrupted();  // a chain may run for seconds
        state.startIteration();
        PathSample proposed = evaluator.evaluate(state, depth, ts);
        Float a = current.y > 0 ? std::min(Float(1), proposed.y / current.y) : Float(1);
        splat(proposed, a);
        splat(current, 1 - a);
        ++ts.stats.proposals;
        bool chance = state.uniform() < a;
        bool forced = !chance && settings.maxConsecutiveRejects > 0 &&
                      rejects >= settings.maxConsecutiveRejects && proposed.y > 0;
        if (chance || forced) {
          current = proposed;
          state.accept();
          ++ts.stats.accepted;
          if (forced) ++ts.stats.forcedAccepts;
          rejects = 0;
        } else {
          state.reject();
          ++rejects;
        }
      }
      progress.update(1);
    };
    parallelFor(taskArena, 0, chains, [&](int c) { runChain(c); });
  }

  RenderResult result;
  for (const ThreadState& ts : threadStates) {
    result.rays += ts.rays;
    result.nonFiniteSamples += ts.nonFinite;
    if (stats) {
      stats->proposals += ts.stats.proposals;
      stats->accepted += ts.stats.accepted;
      stats->forcedAccepts += ts.stats.forcedAccepts;
    }
  }
  result.samples = uint64_t(std::max<int64_t>(totalMutations, 0));
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace candela
