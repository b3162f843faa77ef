// Sampler "name" -> Sampler, with pbrt-v2's parameter names and defaults (lrt draft App. C) and,
// for the samplers pbrt-v3 added, pbrt-v3's (pbrt-v3 file format documentation, "Samplers").
#include <cmath>
#include <iostream>

#include "samplers/adaptive_sampler.h"
#include "samplers/best_candidate_sampler.h"
#include "samplers/halton_sampler.h"
#include "samplers/lowdiscrepancy_sampler.h"
#include "samplers/max_min_dist_matrices.h"
#include "samplers/maxmindist_sampler.h"
#include "samplers/random_sampler.h"
#include "samplers/sampler.h"
#include "samplers/sobol_sampler.h"
#include "samplers/stratified_sampler.h"
#include "samplers/zero_two_sequence_sampler.h"

namespace candela {

namespace {

// Large enough for any practical render, small enough that counts and indices fit in 32 bits.
constexpr int kMaxSamplesPerPixel = 1 << 24;
constexpr int kMaxBestCandidateSamples = 1 << 16;

int positiveCount(const ParamSet& params, const std::string& name, int def, const FileLoc& loc) {
  int v = params.getOneInt(name, def);
  if (v < 1)
    throw SceneError(params.locationOf(name, loc),
                     "\"" + name + "\" must be at least 1, got " + std::to_string(v));
  if (v > kMaxSamplesPerPixel)
    throw SceneError(params.locationOf(name, loc), "\"" + name + "\" is too large (at most " +
                                                       std::to_string(kMaxSamplesPerPixel) + ")");
  return v;
}

// lrt writes "integer jitter" 1; pbrt-v2 "bool jitter" "true". Both mean the same.
bool jitterParam(const ParamSet& params) {
  const ParamItem* item = params.find("jitter");
  if (item && item->type == ParamType::Integer) return params.getOneInt("jitter", 1) != 0;
  return params.getOneBool("jitter", true);
}

// xs * ys == spp with xs >= ys and the pair as close to square as spp's divisors allow.
void factorSamples(int spp, int* xs, int* ys) {
  int d = int(std::sqrt(double(spp)));
  while (d > 1 && spp % d != 0) --d;
  *ys = d;
  *xs = spp / d;
}

void warnAt(const SamplerWarning& warn, const FileLoc& loc, const std::string& message) {
  if (warn)
    warn(loc, message);
  else
    std::cerr << loc.str() << ": warning: " << message << "\n";
}

// The (0,2)-sequence's stratification needs a power of two per pixel (pbrt-v2 rounds up too).
int powerOfTwoCount(int n, const std::string& what, const FileLoc& loc,
                    const SamplerWarning& warn) {
  int p = 1;
  while (p < n) p *= 2;
  if (p != n)
    warnAt(warn, loc,
           what + " " + std::to_string(n) + " rounded up to the power of two " + std::to_string(p));
  return p;
}

// The scene's count is read (so validated, and not reported unused) even when --spp overrides it.
// pbrt-v2's samplers default to 4 samples per pixel, pbrt-v3's to 16.
int sampleCount(const ParamSet& params, int sppOverride, const FileLoc& loc, int def = 4) {
  int sceneCount = positiveCount(params, "pixelsamples", def, loc);
  return sppOverride > 0 ? sppOverride : sceneCount;
}

// The count of a sampler that needs a power of two, rounded up with a warning that names where the
// count came from: the command line's --spp, or the scene's parameter.
int powerOfTwoSampleCount(const std::string& sampler, const ParamSet& params, int sppOverride,
                          int def, const FileLoc& loc, const SamplerWarning& warn) {
  int count = sampleCount(params, sppOverride, loc, def);
  return sppOverride > 0
             ? powerOfTwoCount(count, sampler + " sampler: --spp", FileLoc{"--spp", 0, 0}, warn)
             : powerOfTwoCount(count, sampler + " sampler: pixelsamples",
                               params.locationOf("pixelsamples", loc), warn);
}

// pbrt-v3's pixel samplers' "dimensions": how many 1D and how many 2D dimensions are stratified.
int dimensionCount(const std::string& sampler, const ParamSet& params, const FileLoc& loc) {
  int v = params.getOneInt("dimensions", 4);
  if (v < 1)
    throw SceneError(
        params.locationOf("dimensions", loc),
        sampler + " sampler: \"dimensions\" must be at least 1, got " + std::to_string(v));
  return v;
}

std::unique_ptr<Sampler> createMaxMinDist(const ParamSet& params, uint64_t seed, int sppOverride,
                                          const FileLoc& loc, const SamplerWarning& warn) {
  int spp = powerOfTwoSampleCount("maxmindist", params, sppOverride, 16, loc, warn);
  int dims = dimensionCount("maxmindist", params, loc);
  // pbrt-v3 lowers larger counts with a warning too.
  constexpr int kMax = 1 << kMaxMinDistLog2Max;
  if (spp > kMax) {
    warnAt(warn, sppOverride > 0 ? FileLoc{"--spp", 0, 0} : params.locationOf("pixelsamples", loc),
           "maxmindist sampler: at most " + std::to_string(kMax) + " samples per pixel, " +
               std::to_string(spp) + " lowered to " + std::to_string(kMax));
    spp = kMax;
  }
  return std::make_unique<MaxMinDistSampler>(spp, dims, seed);
}

std::unique_ptr<Sampler> createAdaptive(const ParamSet& params, uint64_t seed, int sppOverride,
                                        const FileLoc& loc, const SamplerWarning& warn) {
  int minSamples = positiveCount(params, "minsamples", 4, loc);
  int maxSamples = positiveCount(params, "maxsamples", 32, loc);
  if (sppOverride > 0) maxSamples = sppOverride;
  minSamples = powerOfTwoCount(minSamples, "adaptive sampler: minsamples",
                               params.locationOf("minsamples", loc), warn);
  maxSamples = sppOverride > 0 ? powerOfTwoCount(maxSamples, "adaptive sampler: --spp",
                                                 FileLoc{"--spp", 0, 0}, warn)
                               : powerOfTwoCount(maxSamples, "adaptive sampler: maxsamples",
                                                 params.locationOf("maxsamples", loc), warn);
  if (sppOverride > 0) {
    minSamples = std::min(minSamples, maxSamples);
  } else if (minSamples > maxSamples) {
    throw SceneError(params.locationOf("minsamples", loc),
                     "adaptive sampler: minsamples " + std::to_string(minSamples) +
                         " exceeds maxsamples " + std::to_string(maxSamples));
  }
  std::string method = params.getOneString("method", "contrast");
  AdaptiveMethod m;
  if (method == "contrast")
    m = AdaptiveMethod::Contrast;
  else if (method == "shapeid")
    m = AdaptiveMethod::ShapeId;
  else
    throw SceneError(
        params.locationOf("method", loc),
        "adaptive sampler: unknown method \"" + method + "\" (known: contrast, shapeid)");
  return std::make_unique<AdaptiveSampler>(minSamples, maxSamples, m, seed);
}

}  // namespace

std::unique_ptr<Sampler> createSampler(const std::string& name, const ParamSet& params,
                                       uint64_t seed, int sppOverride, const FileLoc& loc,
                                       const SamplerWarning& warn, SamplerDefaults defaults) {
  const bool v3 = defaults == SamplerDefaults::PbrtV3;
  if (sppOverride < 0)
    throw SceneError(loc, "samples per pixel must be positive, got " + std::to_string(sppOverride));
  if (sppOverride > kMaxSamplesPerPixel)
    throw SceneError(loc, "samples per pixel " + std::to_string(sppOverride) + " is too large");
  if (name == "random")
    return std::make_unique<RandomSampler>(sampleCount(params, sppOverride, loc), seed);
  if (name == "stratified") {
    int xs = positiveCount(params, "xsamples", v3 ? 4 : 2, loc);
    int ys = positiveCount(params, "ysamples", v3 ? 4 : 2, loc);
    bool jitter = jitterParam(params);
    // "pixelsamples" (the other samplers' count) is accepted when no strata are given.
    if (params.find("pixelsamples") && !params.find("xsamples") && !params.find("ysamples"))
      factorSamples(positiveCount(params, "pixelsamples", 4, loc), &xs, &ys);
    if (sppOverride > 0) factorSamples(sppOverride, &xs, &ys);
    if (int64_t(xs) * int64_t(ys) > kMaxSamplesPerPixel)
      throw SceneError(loc, "stratified sampler: xsamples * ysamples is too large");
    return std::make_unique<StratifiedSampler>(xs, ys, jitter, seed);
  }
  if (name == "lowdiscrepancy")
    return std::make_unique<LowDiscrepancySampler>(
        powerOfTwoSampleCount(name, params, sppOverride, 4, loc, warn), seed);
  if (name == "02sequence") {
    int spp = powerOfTwoSampleCount(name, params, sppOverride, 16, loc, warn);
    return std::make_unique<ZeroTwoSequenceSampler>(spp, dimensionCount(name, params, loc), seed);
  }
  if (name == "maxmindist") return createMaxMinDist(params, seed, sppOverride, loc, warn);
  if (name == "sobol")
    return std::make_unique<SobolSampler>(
        powerOfTwoSampleCount(name, params, sppOverride, 16, loc, warn), seed);
  if (name == "halton")
    return std::make_unique<HaltonSampler>(sampleCount(params, sppOverride, loc, v3 ? 16 : 4),
                                           seed);
  if (name == "bestcandidate") {
    int spp = sampleCount(params, sppOverride, loc);
    // The pattern is generated when the sampler is made, in time about linear in the count.
    if (spp > kMaxBestCandidateSamples)
      throw SceneError(params.locationOf("pixelsamples", loc),
                       "bestcandidate sampler: at most " +
                           std::to_string(kMaxBestCandidateSamples) + " samples per pixel, got " +
                           std::to_string(spp) + " (lowdiscrepancy and halton take more)");
    return std::make_unique<BestCandidateSampler>(spp, seed);
  }
  if (name == "adaptive") return createAdaptive(params, seed, sppOverride, loc, warn);
  throw SceneError(loc, "unknown sampler \"" + name +
                            "\" (known: random, stratified, lowdiscrepancy, halton, "
                            "bestcandidate, adaptive, 02sequence, maxmindist, sobol)");
}

}  // namespace candela
