// Sampler "name" -> Sampler, with pbrt-v2's parameter names and defaults (lrt draft App. C).
#include <cmath>

#include "samplers/random_sampler.h"
#include "samplers/sampler.h"
#include "samplers/stratified_sampler.h"

namespace candela {

namespace {

int positiveCount(const ParamSet& params, const std::string& name, int def, const FileLoc& loc) {
  int v = params.getOneInt(name, def);
  if (v < 1)
    throw SceneError(params.locationOf(name, loc),
                     "\"" + name + "\" must be at least 1, got " + std::to_string(v));
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

}  // namespace

std::unique_ptr<Sampler> createSampler(const std::string& name, const ParamSet& params,
                                       uint64_t seed, int sppOverride, const FileLoc& loc) {
  if (sppOverride < 0)
    throw SceneError(loc, "samples per pixel must be positive, got " + std::to_string(sppOverride));
  if (name == "random") {
    int spp = positiveCount(params, "pixelsamples", 4, loc);
    return std::make_unique<RandomSampler>(sppOverride > 0 ? sppOverride : spp, seed);
  }
  if (name == "stratified") {
    int xs = positiveCount(params, "xsamples", 2, loc);
    int ys = positiveCount(params, "ysamples", 2, loc);
    bool jitter = jitterParam(params);
    // "pixelsamples" (the other samplers' count) is accepted when no strata are given.
    if (params.find("pixelsamples") && !params.find("xsamples") && !params.find("ysamples"))
      factorSamples(positiveCount(params, "pixelsamples", 4, loc), &xs, &ys);
    if (sppOverride > 0) factorSamples(sppOverride, &xs, &ys);
    if (int64_t(xs) * int64_t(ys) > (int64_t(1) << 30))
      throw SceneError(loc, "stratified sampler: xsamples * ysamples is too large");
    return std::make_unique<StratifiedSampler>(xs, ys, jitter, seed);
  }
  throw SceneError(loc, "unknown sampler \"" + name + "\" (known: random, stratified)");
}

}  // namespace candela
