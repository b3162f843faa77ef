// Several `Volume` regions in one scene (lrt draft §12.4's VolumeList; pbrt 2e's AggregateVolume):
// their coefficients add, and the phase function at a point is that of the region scattering the
// most there (largest σs, by its channel average).
#pragma once

#include <memory>
#include <vector>

#include "media/medium.h"

namespace candela {

class AggregateVolume : public Medium {
 public:
  explicit AggregateVolume(std::vector<std::unique_ptr<Medium>> regions);
  Bounds3f worldBound() const override { return bound_; }
  // The union of the regions' ranges (from the first entry to the last exit).
  bool intersectP(const Ray& ray, Float* t0, Float* t1) const override;
  MediumPoint at(const Point3f& p, Float time) const override;
  PhaseFunction phase(const Point3f& p, Float time) const override;
  // The sum of the regions' optical depths, each closed-form where the region has one.
  Spectrum opticalDepth(const Ray& ray, Float t0, Float t1, Float stepSize,
                        Float offset) const override;
  Spectrum majorant(const Ray& ray, Float t0, Float t1) const override;
  bool emits() const override;
  size_t size() const { return regions_.size(); }

 private:
  std::vector<std::unique_ptr<Medium>> regions_;
  Bounds3f bound_;
};

}  // namespace candela
