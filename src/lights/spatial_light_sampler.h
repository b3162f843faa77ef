// pbrt-v3's "spatial" light sampling (its lightsamplestrategy's default): the scene's
// bounds cut into voxels, up to 64 along the longest axis, and for each voxel a distribution over
// the lights in proportion to the irradiance they send to 128 points spread through it by the
// Halton sequence (one light sample each, no visibility). No light gets less than a thousandth
// of the mean irradiance of one light at one point, since a voxel's points may all miss where a
// light does reach. A voxel's
// distribution is made the first time a point in it asks, by whichever thread asks, and is the
// same whichever does: the choice of light is a pure function of the point and the sample value.
#pragma once

#include <atomic>
#include <memory>
#include <vector>

#include "core/sampling.h"
#include "lights/light_sampler.h"

namespace candela {

class SpatialLightSampler final : public LightSampler {
 public:
  SpatialLightSampler(const std::vector<const Light*>& lights, const Bounds3f& sceneBounds);
  ~SpatialLightSampler() override;
  SpatialLightSampler(const SpatialLightSampler&) = delete;
  SpatialLightSampler& operator=(const SpatialLightSampler&) = delete;

  const Light* sample(const LightSampleContext& at, Float u, Float* pmf) const override;
  Float pmf(const LightSampleContext& at, const Light& light) const override;

  // Voxels along each axis.
  int voxels(int axis) const { return n_[axis]; }
  // The distribution of the voxel holding p (made now if no point in it has asked before).
  const Distribution1D& distributionAt(const Point3f& p) const;

 private:
  Distribution1D makeDistribution(int x, int y, int z) const;

  std::vector<const Light*> lights_;
  LightIndex index_;
  Bounds3f bounds_;
  int n_[3] = {1, 1, 1};
  // One slot per voxel, null until made; owned here.
  std::unique_ptr<std::atomic<const Distribution1D*>[]> voxels_;
};

}  // namespace candela
