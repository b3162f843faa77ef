#include "lights/light_sampler.h"

#include <algorithm>

#include "core/sampling.h"
#include "lights/light_tree_sampler.h"
#include "lights/spatial_light_sampler.h"

namespace candela {

std::optional<LightSampleStrategy> lightSampleStrategyNamed(const std::string& name) {
  if (name == "uniform") return LightSampleStrategy::Uniform;
  if (name == "power") return LightSampleStrategy::Power;
  if (name == "spatial") return LightSampleStrategy::Spatial;
  if (name == "bvh") return LightSampleStrategy::Bvh;
  return std::nullopt;
}

LightIndex::LightIndex(std::span<const Light* const> lights) {
  for (size_t i = 0; i < lights.size(); ++i) index_.emplace(lights[i], int(i));
}

int LightIndex::of(const Light& light) const {
  auto it = index_.find(&light);
  return it == index_.end() ? -1 : it->second;
}

std::vector<Float> lightPowerWeights(std::span<const Light* const> lights) {
  std::vector<Float> w;
  w.reserve(lights.size());
  for (const Light* light : lights) {
    Float y = light->power().y();
    w.push_back(std::isfinite(y) && y > 0 ? y : 0);
  }
  return w;
}

namespace {

class UniformLightSampler final : public LightSampler {
 public:
  explicit UniformLightSampler(const std::vector<const Light*>& lights) : lights_(lights) {}
  const Light* sample(const LightSampleContext&, Float u, Float* pmf) const override {
    int n = int(lights_.size());
    if (n == 0) return *pmf = 0, nullptr;
    *pmf = 1 / Float(n);
    return lights_[size_t(std::min(int(u * Float(n)), n - 1))];
  }
  Float pmf(const LightSampleContext&, const Light&) const override {
    return lights_.empty() ? 0 : 1 / Float(lights_.size());
  }

 private:
  std::vector<const Light*> lights_;
};

// In proportion to each light's power (its luminance); uniformly when no light has any (a scene
// of lights whose power is unknown or zero).
class PowerLightSampler final : public LightSampler {
 public:
  explicit PowerLightSampler(const std::vector<const Light*>& lights)
      : lights_(lights), index_(lights), choice_(weights(lights)) {}
  const Light* sample(const LightSampleContext&, Float u, Float* pmf) const override {
    if (lights_.empty()) return *pmf = 0, nullptr;
    return lights_[size_t(choice_.sampleDiscrete(u, pmf))];
  }
  Float pmf(const LightSampleContext&, const Light& light) const override {
    int i = index_.of(light);
    return i < 0 ? 0 : choice_.discretePmf(i);
  }

 private:
  static std::vector<Float> weights(const std::vector<const Light*>& lights) {
    std::vector<Float> w = lightPowerWeights(lights);
    bool any = std::any_of(w.begin(), w.end(), [](Float x) { return x > 0; });
    if (!any) std::fill(w.begin(), w.end(), Float(1));
    if (w.empty()) w.push_back(1);  // Distribution1D needs a cell; no light is ever returned
    return w;
  }
  std::vector<const Light*> lights_;
  LightIndex index_;
  Distribution1D choice_;
};

}  // namespace

LightSampleStrategy resolvedLightStrategy(LightSampleStrategy strategy, size_t nLights) {
  if (strategy != LightSampleStrategy::SpatialUnlessMany) return strategy;
  return nLights > kSpatialMostLights ? LightSampleStrategy::Bvh : LightSampleStrategy::Spatial;
}

std::string lightStrategyNotice(LightSampleStrategy strategy, size_t nLights) {
  if (strategy != LightSampleStrategy::SpatialUnlessMany || nLights <= kSpatialMostLights)
    return {};
  return "the scene has " + std::to_string(nLights) + " lights, more than " +
         std::to_string(kSpatialMostLights) +
         ": choosing them by a light tree (\"bvh\") rather than pbrt-v3's default \"spatial\", "
         "which takes 128 samples of every light in each voxel (give \"string "
         "lightsamplestrategy\" \"spatial\" to keep it)";
}

std::unique_ptr<LightSampler> createLightSampler(LightSampleStrategy strategy,
                                                 const std::vector<const Light*>& lights,
                                                 const Bounds3f& sceneBounds) {
  switch (resolvedLightStrategy(strategy, lights.size())) {
    case LightSampleStrategy::Uniform:
      return std::make_unique<UniformLightSampler>(lights);
    case LightSampleStrategy::Power:
      return std::make_unique<PowerLightSampler>(lights);
    case LightSampleStrategy::Spatial:
      return std::make_unique<SpatialLightSampler>(lights, sceneBounds);
    case LightSampleStrategy::Bvh:
    case LightSampleStrategy::SpatialUnlessMany:  // resolved above
      return std::make_unique<LightTreeSampler>(lights);
  }
  return nullptr;
}

}  // namespace candela
