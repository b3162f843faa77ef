// Which light a shading point samples for next-event estimation: the three strategies of
// pbrt-v3's lightsamplestrategy parameter (the book picks one light uniformly, pbrt 3e §14.3;
// pbrt-v3's later code added the other two) and pbrt-v4's light tree. "uniform" picks each light
// with the same probability; "power" in proportion to the power it emits; "spatial" in proportion
// to an estimate of the irradiance each light sends into the region of space around the point;
// "bvh" by descending a tree over the lights by each group's importance at the point and its
// normal (Conty Estevez & Kulla 2018, pbrt 4e §12.6). All four are unbiased: the estimate divides
// by the probability of the light chosen, which is not 0 for any light that can send the point
// light, and the integrators' MIS weights use the same probability at the same point.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "lights/light.h"

namespace candela {

// SpatialUnlessMany, no name of its own, is path's and volpath's default in pbrt-v3 scenes:
// pbrt-v3's "spatial", or the light tree for a scene of more than kSpatialMostLights lights,
// where spatial's voxels would each take 128 samples of every light (20,000 triangles of a
// 10,000-quad scene: 372 s to relMSE 1e-2 where the tree takes 3.3 s).
enum class LightSampleStrategy { Uniform, Power, Spatial, Bvh, SpatialUnlessMany };
inline constexpr size_t kSpatialMostLights = 4096;
// The strategy a scene of nLights lights samples by: strategy, SpatialUnlessMany resolved.
LightSampleStrategy resolvedLightStrategy(LightSampleStrategy strategy, size_t nLights);
// What to tell the user when SpatialUnlessMany takes the tree for nLights lights; "" otherwise.
std::string lightStrategyNotice(LightSampleStrategy strategy, size_t nLights);

// "uniform", "power", "spatial" or "bvh"; nullopt for anything else.
std::optional<LightSampleStrategy> lightSampleStrategyNamed(const std::string& name);
// Every name lightSampleStrategyNamed knows, in that order.
inline constexpr const char* kLightSampleStrategyNames[] = {"uniform", "power", "spatial", "bvh"};

// The point a light is chosen for: its position and, on a surface, its geometric normal (zero in
// a medium or where there is none).
struct LightSampleContext {
  Point3f p;
  Normal3f n;
  LightSampleContext(const Point3f& p_, const Normal3f& n_ = Normal3f()) : p(p_), n(n_) {}
  explicit LightSampleContext(const Interaction& it) : p(it.p), n(it.n) {}
};

class LightSampler {
 public:
  virtual ~LightSampler() = default;
  // The light a point samples for u in [0, 1), and the probability of that choice; null (and
  // *pmf 0) when the scene has no light or none can reach the point.
  virtual const Light* sample(const LightSampleContext& at, Float u, Float* pmf) const = 0;
  // The probability that sample(at, u) chooses light, over u.
  virtual Float pmf(const LightSampleContext& at, const Light& light) const = 0;
};

// The position of each light in the scene's list, for the probability of a given light.
class LightIndex {
 public:
  explicit LightIndex(std::span<const Light* const> lights);
  int of(const Light& light) const;  // -1 for a light not in the list

 private:
  std::unordered_map<const Light*, int> index_;
};

// Each light's power as a weight for choosing it: the luminance of power(), 0 where that is not
// a finite positive number. (Also the light choice of photon shooting and light paths.)
std::vector<Float> lightPowerWeights(std::span<const Light* const> lights);

// The sampler of a strategy over a scene's lights (after the lights' preprocess: the power of
// distant and infinite lights depends on the scene's bounds) within the scene's bounds (what the
// spatial strategy's voxels divide).
std::unique_ptr<LightSampler> createLightSampler(LightSampleStrategy strategy,
                                                 const std::vector<const Light*>& lights,
                                                 const Bounds3f& sceneBounds);

}  // namespace candela
