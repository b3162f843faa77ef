#include "integrators/irradiance/irradiance_cache_integrator.h"

#include <array>
#include <chrono>
#include <cmath>
#include <sstream>

#include "accel/embree/embree_device.h"
#include "film/film.h"
#include "integrators/irradiance/irradiance_interpolation.h"
#include "integrators/irradiance/irradiance_prepass.h"
#include "samplers/zero_two_sequence.h"
#include "transport/light_sampling.h"

namespace candela {

namespace {

constexpr int kRhoSamples = 16;

uint32_t fractionBits(Float u) { return uint32_t(double(u) * 0x1p32); }

// The coarsest prepass grid: the largest power of two not above the largest sample spacing, so
// that the first round already places samples about as far apart as they may be.
int firstGridStep(Float maxPixelSpacing) {
  int step = 1;
  while (Float(step * 2) <= maxPixelSpacing && step < (1 << 12)) step *= 2;
  return step;
}

}  // namespace

IrradianceCacheIntegrator::IrradianceCacheIntegrator(const IrradianceCacheSettings& settings)
    : SpecularRecursionIntegrator(settings.maxSpecularDepth),
      settings_(settings),
      // maxangledifference is in degrees; pbrt-v2's code took cos(Degrees(x)), which makes the
      // default 10 an angle of about 68 degrees (notes: seeds-001-003 §2.10).
      cosMaxAngle_(std::cos(radians(settings.maxAngleDifference))),
      paths_(settings.maxIndirectDepth) {}

IrradianceCacheIntegrator::~IrradianceCacheIntegrator() = default;

IrradianceQuery IrradianceCacheIntegrator::query(const SurfaceInteraction& isect,
                                                 bool transmission) const {
  Normal3f n = faceForward(isect.n, isect.wo);
  if (transmission) n = -n;
  // The side of a square with the area of the pixel's footprint (pbrt 2e §15.5.1).
  Float pixelSpacing = std::sqrt(cross(isect.dpdx, isect.dpdy).length());
  return {Interaction(isect.p, isect.n, isect.pError, isect.wo, isect.time), n, pixelSpacing};
}

IrradianceSample IrradianceCacheIntegrator::newSample(const IrradianceQuery& q, const Scene& scene,
                                                      uint64_t seed, RayStats& stats) const {
  IrradianceEstimate est =
      estimateIrradiance(q, scene, paths_, settings_.nSamples, settings_.nFilter, seed, stats);
  return {q.at.p, q.n, est.E, validityRadius(est, q.pixelSpacing, settings_, sceneSize_)};
}

void IrradianceCacheIntegrator::preprocess(const Scene&, const PreprocessOptions& options) {
  if (!options.quick || quickApplied_) return;
  quickApplied_ = true;
  settings_.nSamples = std::max(1, settings_.nSamples / 16);
  settings_.nFilter = std::min(settings_.nFilter, settings_.nSamples - 1);
}

RenderResult IrradianceCacheIntegrator::renderSamples(const RenderInputs& in, Film& film,
                                                      const RenderOptions& options) {
  auto start = std::chrono::steady_clock::now();
  RayStats prepassRays = prepare(in.scene, in.camera, in.sampler, film,
                                 {options.nThreads, options.quiet, enableFlushToZero});
  const double prepassSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  SampleLoop loop = sampleLoop(in, film);
  loop.rayDifferentials = true;
  RenderResult result = renderPixelSamples(in, film, options, loop);
  result.rays += prepassRays;
  result.seconds += prepassSeconds;
  return result;
}

RayStats IrradianceCacheIntegrator::prepare(const Scene& scene, const Camera& camera,
                                            const Sampler& sampler, const Film& film,
                                            const PrepassOptions& options) {
  if (prepared_) return {};
  prepared_ = true;
  if (settings_.maxError == 0) return {};  // the lrt draft's "cache nothing"
  auto start = std::chrono::steady_clock::now();
  // Padded so that hit points a rounding error outside the scene's bounds are still found
  // (pbrt 2e §15.5).
  Bounds3f bounds = scene.worldBound();
  if (!bounds.empty()) {
    Vector3f pad = bounds.diagonal() * 0.01f;
    bounds = Bounds3f(bounds.pMin - pad, bounds.pMax + pad);
    sceneSize_ = bounds.diagonal().length();
  }
  cache_ = std::make_unique<IrradianceOctree>(bounds);

  PrepassPlan plan;
  plan.resolution = film.fullResolution();
  plan.firstStep = firstGridStep(settings_.maxPixelSpacing);
  plan.minWeight = settings_.minWeight;
  plan.cosMaxAngle = cosMaxAngle_;
  plan.minPixelSpacing = settings_.minPixelSpacing;
  const IrradianceOctree& cache = *cache_;
  auto findUncached = [&](const RayDifferential& ray, IntegratorContext& ctx,
                          std::vector<IrradianceQuery>* uncached) {
    traceWith(ray, scene, ctx,
              [&](const SurfaceInteraction& isect, const BSDF& bsdf, IntegratorContext&) {
                for (bool transmission : {false, true}) {
                  int flags = (transmission ? kTransmission : kReflection) | kDiffuse | kGlossy;
                  if (bsdf.numComponents(flags) == 0) continue;
                  IrradianceQuery q = query(isect, transmission);
                  if (!interpolateIrradiance(cache, q.at.p, q.n, cosMaxAngle_)
                           .acceptable(settings_.minWeight))
                    uncached->push_back(q);
                }
                return Spectrum(0);
              });
  };
  auto compute = [&](const IrradianceQuery& q, uint64_t seed, RayStats& stats) {
    return newSample(q, scene, seed, stats);
  };
  PrepassResult r =
      fillIrradianceCache(*cache_, camera, sampler, plan, findUncached, compute, options);
  prepassEstimates_ = r.estimated;
  prepassUncached_ = r.uncached;
  prepassSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r.rays;
}

Spectrum IrradianceCacheIntegrator::directLight(const SurfaceInteraction& isect, const BSDF& bsdf,
                                                const Scene& scene, IntegratorContext& ctx) const {
  Spectrum l = uniformSampleAllLights(isect, bsdf, scene, ctx);
  l += indirectLight(isect, bsdf, false, scene, ctx);
  l += indirectLight(isect, bsdf, true, scene, ctx);
  return l;
}

Spectrum IrradianceCacheIntegrator::indirectLight(const SurfaceInteraction& isect, const BSDF& bsdf,
                                                  bool transmission, const Scene& scene,
                                                  IntegratorContext& ctx) const {
  int flags = (transmission ? kTransmission : kReflection) | kDiffuse | kGlossy;
  if (bsdf.numComponents(flags) == 0) return Spectrum(0);
  // Drawn whether or not the cache answers, so that later dimensions do not depend on it.
  Point2f rhoScramble = ctx.sampler.get2D();
  Point2f seedBits = ctx.sampler.get2D();
  IrradianceQuery q = query(isect, transmission);
  Spectrum E;
  InterpolatedIrradiance cached;
  if (cache_) cached = interpolateIrradiance(*cache_, q.at.p, q.n, cosMaxAngle_);
  if (cached.acceptable(settings_.minWeight)) {
    E = cached.E();
  } else if (cached.sumWeight > 0) {
    // Below minweight but not empty: the point lies at the edge of samples the prepass placed
    // for the pixel centres around it. Their average is smoother than a fresh estimate.
    renderWeakLookups_.fetch_add(1, std::memory_order_relaxed);
    E = cached.E();
  } else {
    renderMisses_.fetch_add(1, std::memory_order_relaxed);
    uint64_t seed = hashValues({fractionBits(seedBits.x), fractionBits(seedBits.y), 0x1cu});
    E = estimateIrradiance(q, scene, paths_, settings_.nSamples, settings_.nFilter, seed, ctx.stats)
            .E;
  }
  if (E.isBlack()) return Spectrum(0);
  // rho_hd(wo) from a scrambled (0,2)-sequence: exact for Lambertian components, which ignore
  // the points.
  std::array<Point2f, kRhoSamples> u;
  uint32_t sx = fractionBits(rhoScramble.x), sy = fractionBits(rhoScramble.y);
  for (int i = 0; i < kRhoSamples; ++i)
    u[size_t(i)] = Point2f(bitsToUnitFloat(vanDerCorputBits(uint32_t(i), sx)),
                           bitsToUnitFloat(sobol2Bits(uint32_t(i), sy)));
  return bsdf.rho(isect.wo, u, flags) * E * kInvPi;
}

std::string IrradianceCacheIntegrator::statsReport() const {
  std::ostringstream os;
  os << "Irradiance cache\n";
  if (!cache_) {
    os << "  no cache (maxerror 0): every point estimated afresh, " << renderMisses() << "\n";
    return os.str();
  }
  os << "  samples  " << cache_->size() << "\n";
  os << "  memory  " << (cache_->memoryBytes() + 1023) / 1024 << " KiB\n";
  os << "  prepass: points uncached when their round began  " << prepassUncached_ << ", estimated  "
     << prepassEstimates_ << ", " << prepassSeconds_ << " s\n";
  os << "  render: points below minweight, interpolated anyway  " << renderWeakLookups_.load()
     << ", with no sample, estimated afresh (not stored)  " << renderMisses() << "\n";
  return os.str();
}

}  // namespace candela
