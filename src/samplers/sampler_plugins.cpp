#include "samplers/sampler_plugins.h"

#include <cmath>
#include <iostream>

#include "samplers/adaptive_sampler.h"
#include "samplers/best_candidate_sampler.h"
#include "samplers/halton_sampler.h"
#include "samplers/lowdiscrepancy_sampler.h"
#include "samplers/max_min_dist_matrices.h"
#include "samplers/maxmindist_sampler.h"
#include "samplers/random_sampler.h"
#include "samplers/sobol_sampler.h"
#include "samplers/stratified_sampler.h"
#include "samplers/zero_two_sequence_sampler.h"

namespace candela {

namespace {

constexpr int kMaxBestCandidateSamples = 1 << 16;  // the table words it: within [1, 65536]

int positiveCount(const ParamSet& params, const std::string& name, int def, const FileLoc& loc) {
  return params.getOneInt(name, def, ValueRange::within(1, kMaxSamplesPerPixel), loc);
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
int dimensionCount(const ParamSet& params, const FileLoc& loc) {
  return params.getOneInt("dimensions", 4, ValueRange::atLeast(1), loc);
}

std::unique_ptr<Sampler> createRandom(const ParamSet& params, uint64_t seed, int sppOverride,
                                      const FileLoc& loc, const SamplerWarning& /*warn*/,
                                      SamplerDefaults /*defaults*/) {
  return std::make_unique<RandomSampler>(sampleCount(params, sppOverride, loc), seed);
}

std::unique_ptr<Sampler> createStratified(const ParamSet& params, uint64_t seed, int sppOverride,
                                          const FileLoc& loc, const SamplerWarning& /*warn*/,
                                          SamplerDefaults defaults) {
  const bool v3 = defaults == SamplerDefaults::PbrtV3;
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

std::unique_ptr<Sampler> createLowDiscrepancy(const ParamSet& params, uint64_t seed,
                                              int sppOverride, const FileLoc& loc,
                                              const SamplerWarning& warn,
                                              SamplerDefaults /*defaults*/) {
  return std::make_unique<LowDiscrepancySampler>(
      powerOfTwoSampleCount("lowdiscrepancy", params, sppOverride, 4, loc, warn), seed);
}

std::unique_ptr<Sampler> createHalton(const ParamSet& params, uint64_t seed, int sppOverride,
                                      const FileLoc& loc, const SamplerWarning& /*warn*/,
                                      SamplerDefaults defaults) {
  const bool v3 = defaults == SamplerDefaults::PbrtV3;
  return std::make_unique<HaltonSampler>(sampleCount(params, sppOverride, loc, v3 ? 16 : 4), seed);
}

std::unique_ptr<Sampler> createBestCandidate(const ParamSet& params, uint64_t seed, int sppOverride,
                                             const FileLoc& loc, const SamplerWarning& /*warn*/,
                                             SamplerDefaults /*defaults*/) {
  int spp = sampleCount(params, sppOverride, loc);
  // The pattern is generated when the sampler is made, in time about linear in the count.
  if (spp > kMaxBestCandidateSamples)
    throw SceneError(params.locationOf("pixelsamples", loc),
                     "bestcandidate sampler: \"pixelsamples\" must be within [1, " +
                         std::to_string(kMaxBestCandidateSamples) + "] (got " +
                         std::to_string(spp) + "; lowdiscrepancy and halton take more)");
  return std::make_unique<BestCandidateSampler>(spp, seed);
}

std::unique_ptr<Sampler> createAdaptive(const ParamSet& params, uint64_t seed, int sppOverride,
                                        const FileLoc& loc, const SamplerWarning& warn,
                                        SamplerDefaults /*defaults*/) {
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
  std::string method = params.getOneString("method", "contrast", {"contrast", "shapeid"}, loc);
  AdaptiveMethod m = method == "contrast" ? AdaptiveMethod::Contrast : AdaptiveMethod::ShapeId;
  return std::make_unique<AdaptiveSampler>(minSamples, maxSamples, m, seed);
}

std::unique_ptr<Sampler> createZeroTwoSequence(const ParamSet& params, uint64_t seed,
                                               int sppOverride, const FileLoc& loc,
                                               const SamplerWarning& warn,
                                               SamplerDefaults /*defaults*/) {
  int spp = powerOfTwoSampleCount("02sequence", params, sppOverride, 16, loc, warn);
  return std::make_unique<ZeroTwoSequenceSampler>(spp, dimensionCount(params, loc), seed);
}

std::unique_ptr<Sampler> createMaxMinDist(const ParamSet& params, uint64_t seed, int sppOverride,
                                          const FileLoc& loc, const SamplerWarning& warn,
                                          SamplerDefaults /*defaults*/) {
  int spp = powerOfTwoSampleCount("maxmindist", params, sppOverride, 16, loc, warn);
  int dims = dimensionCount(params, loc);
  // pbrt-v3 lowers larger counts with a warning too.
  constexpr int kMax = 1 << kMaxMinDistLog2Max;
  static_assert(kMax == 65536, "kMaxMinDistParams words the limit");
  if (spp > kMax) {
    warnAt(warn, sppOverride > 0 ? FileLoc{"--spp", 0, 0} : params.locationOf("pixelsamples", loc),
           "maxmindist sampler: at most " + std::to_string(kMax) + " samples per pixel, " +
               std::to_string(spp) + " lowered to " + std::to_string(kMax));
    spp = kMax;
  }
  return std::make_unique<MaxMinDistSampler>(spp, dims, seed);
}

std::unique_ptr<Sampler> createSobol(const ParamSet& params, uint64_t seed, int sppOverride,
                                     const FileLoc& loc, const SamplerWarning& warn,
                                     SamplerDefaults /*defaults*/) {
  return std::make_unique<SobolSampler>(
      powerOfTwoSampleCount("sobol", params, sppOverride, 16, loc, warn), seed);
}

// The rule of every sample count: at least 1, at most kMaxSamplesPerPixel.
constexpr std::string_view kCountRule = "within [1, 16777216]";
static_assert(kMaxSamplesPerPixel == 16777216, "kCountRule words kMaxSamplesPerPixel");

constexpr ParamSpec kRandomParams[] = {
    {"pixelsamples", "integer", "4", "", kCountRule, kAllDialects, "samples per pixel"},
};

constexpr ParamSpec kStratifiedParams[] = {
    {"xsamples", "integer", "2", "4", kCountRule, kAllDialects, "strata across a pixel"},
    {"ysamples", "integer", "2", "4", kCountRule, kAllDialects, "strata down a pixel"},
    {"jitter", "bool", "true", "", "", kAllDialects,
     "jitter each sample within its stratum (lrt writes an integer 0 or 1)"},
    {"pixelsamples", "integer", "(none)", "", kCountRule, kCandela,
     "without xsamples and ysamples: strata as square as this count divides into"},
};

constexpr ParamSpec kLowDiscrepancyParams[] = {
    {"pixelsamples", "integer", "4", "", kCountRule, kAllDialects,
     "samples per pixel, rounded up to a power of two"},
};

constexpr ParamSpec kHaltonParams[] = {
    {"pixelsamples", "integer", "4", "16", kCountRule, kAllDialects, "samples per pixel"},
};

constexpr ParamSpec kBestCandidateParams[] = {
    {"pixelsamples", "integer", "4", "", "within [1, 65536]", kLrt | kPbrtV2, "samples per pixel"},
};

constexpr ParamSpec kAdaptiveParams[] = {
    {"minsamples", "integer", "4", "", kCountRule, kLrt | kPbrtV2,
     "samples every pixel takes, rounded up to a power of two"},
    {"maxsamples", "integer", "32", "", kCountRule, kLrt | kPbrtV2,
     "samples a pixel that needs more takes, rounded up to a power of two"},
    {"method", "string", "contrast", "", "one of contrast, shapeid", kLrt | kPbrtV2,
     "what asks for more samples"},
};

constexpr ParamSpec kZeroTwoSequenceParams[] = {
    {"pixelsamples", "integer", "16", "", kCountRule, kPbrtV3,
     "samples per pixel, rounded up to a power of two"},
    {"dimensions", "integer", "4", "", "at least 1", kPbrtV3,
     "1D and 2D dimensions stratified per pixel"},
};

constexpr ParamSpec kMaxMinDistParams[] = {
    {"pixelsamples", "integer", "16", "", kCountRule, kPbrtV3,
     "samples per pixel, rounded up to a power of two (more than 65536 lowered to it)"},
    {"dimensions", "integer", "4", "", "at least 1", kPbrtV3,
     "1D and 2D dimensions stratified per pixel"},
};

constexpr ParamSpec kSobolParams[] = {
    {"pixelsamples", "integer", "16", "", kCountRule, kPbrtV3,
     "samples per pixel, rounded up to a power of two"},
};

const SamplerPlugin kSamplers[] = {
    {{"sampler", "random", kAllDialects, "independent uniform samples (pbrt 4e §8.3)",
      kRandomParams},
     createRandom},
    {{"sampler", "stratified", kAllDialects,
      "jittered strata, shuffled across dimensions (lrt draft §7.3)", kStratifiedParams},
     createStratified},
    {{"sampler", "lowdiscrepancy", kAllDialects,
      "scrambled (0,2)-sequence per pixel (lrt draft §7.5.3)", kLowDiscrepancyParams},
     createLowDiscrepancy},
    {{"sampler", "halton", kAllDialects, "Halton points per pixel (lrt draft §7.5.2)",
      kHaltonParams},
     createHalton},
    {{"sampler", "bestcandidate", kLrt | kPbrtV2,
      "a tiled best-candidate (blue-noise) pattern (lrt draft §7.6)", kBestCandidateParams},
     createBestCandidate},
    {{"sampler", "adaptive", kLrt | kPbrtV2,
      "more samples where the first ones disagree (lrt draft §7.8, exercise)", kAdaptiveParams},
     createAdaptive},
    {{"sampler", "02sequence", kPbrtV3, "(0,2)-sequence per pixel (pbrt 3e §7.5)",
      kZeroTwoSequenceParams},
     createZeroTwoSequence},
    {{"sampler", "maxmindist", kPbrtV3, "maximal-minimum-distance points per pixel (pbrt 3e §7.6)",
      kMaxMinDistParams},
     createMaxMinDist},
    {{"sampler", "sobol", kPbrtV3, "Owen-scrambled Sobol' points per pixel (pbrt 3e §7.7)",
      kSobolParams},
     createSobol},
};

}  // namespace

std::span<const SamplerPlugin> samplerPlugins() { return kSamplers; }

}  // namespace candela
