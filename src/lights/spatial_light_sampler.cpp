#include "lights/spatial_light_sampler.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "samplers/radical_inverse.h"

namespace candela {

namespace {

constexpr int kMaxVoxels = 64;     // along the longest axis of the scene's bounds
constexpr int kVoxelPoints = 128;  // where a voxel's irradiance is estimated
constexpr Float kFloorFraction = 0.001f;

}  // namespace

SpatialLightSampler::SpatialLightSampler(const std::vector<const Light*>& lights,
                                         const Bounds3f& sceneBounds)
    : lights_(lights), index_(lights), bounds_(sceneBounds) {
  Vector3f d = bounds_.diagonal();
  Float longest = std::max({d.x, d.y, d.z});
  for (int a = 0; a < 3; ++a)
    n_[a] = longest > 0 && std::isfinite(longest)
                ? std::max(1, int(std::round(d[a] / longest * Float(kMaxVoxels))))
                : 1;
  size_t count = size_t(n_[0]) * size_t(n_[1]) * size_t(n_[2]);
  voxels_ = std::make_unique<std::atomic<const Distribution1D*>[]>(count);
  for (size_t i = 0; i < count; ++i) voxels_[i].store(nullptr, std::memory_order_relaxed);
}

SpatialLightSampler::~SpatialLightSampler() {
  size_t count = size_t(n_[0]) * size_t(n_[1]) * size_t(n_[2]);
  for (size_t i = 0; i < count; ++i) delete voxels_[i].load(std::memory_order_relaxed);
}

Distribution1D SpatialLightSampler::makeDistribution(int x, int y, int z) const {
  const int at[3] = {x, y, z};
  Point3f lo, hi;
  for (int a = 0; a < 3; ++a) {
    lo[a] = lerp(Float(at[a]) / Float(n_[a]), bounds_.pMin[a], bounds_.pMax[a]);
    hi[a] = lerp(Float(at[a] + 1) / Float(n_[a]), bounds_.pMin[a], bounds_.pMax[a]);
  }
  std::vector<Float> contribution(lights_.size(), 0);
  for (int i = 0; i < kVoxelPoints; ++i) {
    Point3f p(lerp(radicalInverse(uint32_t(i), 2), lo.x, hi.x),
              lerp(radicalInverse(uint32_t(i), 3), lo.y, hi.y),
              lerp(radicalInverse(uint32_t(i), 5), lo.z, hi.z));
    Interaction ref(p, 0);
    for (size_t j = 0; j < lights_.size(); ++j) {
      Vector3f wi;
      Float pdf = 0;
      VisibilityTester vis;
      Spectrum li = lights_[j]->sampleLi(ref, Point2f(0.5f, 0.5f), &wi, &pdf, &vis);
      Float e = pdf > 0 ? li.y() / pdf : 0;
      if (std::isfinite(e) && e > 0) contribution[j] += e;
    }
  }
  // Contributions whose sum overflows tell nothing apart: uniform. Otherwise the floor, 1 when no
  // light reaches any point.
  Float sum = std::accumulate(contribution.begin(), contribution.end(), Float(0));
  if (!std::isfinite(sum)) {
    std::fill(contribution.begin(), contribution.end(), Float(1));
  } else {
    Float mean = sum / Float(kVoxelPoints * std::max<size_t>(1, lights_.size()));
    Float floor = mean > 0 ? kFloorFraction * mean : 1;
    for (Float& c : contribution) c = std::max(c, floor);
  }
  if (contribution.empty()) contribution.push_back(1);
  return Distribution1D(std::move(contribution));
}

const Distribution1D& SpatialLightSampler::distributionAt(const Point3f& p) const {
  int at[3];
  for (int a = 0; a < 3; ++a) {
    Float extent = bounds_.pMax[a] - bounds_.pMin[a];
    Float v = extent > 0 ? (p[a] - bounds_.pMin[a]) / extent * Float(n_[a]) : 0;
    // Points outside the bounds go to the nearest voxel, NaN to the first (compared as floats:
    // a far point's voxel number would overflow an int).
    at[a] = !(v > 0) ? 0 : v >= Float(n_[a]) ? n_[a] - 1 : int(v);
  }
  size_t slot = (size_t(at[2]) * size_t(n_[1]) + size_t(at[1])) * size_t(n_[0]) + size_t(at[0]);
  std::atomic<const Distribution1D*>& cell = voxels_[slot];
  const Distribution1D* d = cell.load(std::memory_order_acquire);
  if (d) return *d;
  auto made = std::make_unique<const Distribution1D>(makeDistribution(at[0], at[1], at[2]));
  const Distribution1D* expected = nullptr;
  // Another thread may have made the same distribution meanwhile: keep the first.
  if (cell.compare_exchange_strong(expected, made.get(), std::memory_order_acq_rel,
                                   std::memory_order_acquire))
    return *made.release();
  return *expected;
}

const Light* SpatialLightSampler::sample(const LightSampleContext& at, Float u, Float* pmf) const {
  if (lights_.empty()) return *pmf = 0, nullptr;
  return lights_[size_t(distributionAt(at.p).sampleDiscrete(u, pmf))];
}

Float SpatialLightSampler::pmf(const LightSampleContext& at, const Light& light) const {
  int i = index_.of(light);
  return i < 0 ? 0 : distributionAt(at.p).discretePmf(i);
}

}  // namespace candela
