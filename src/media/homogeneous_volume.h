// `Volume "homogeneous"` (lrt draft §12.2; pbrt 2e §11.3.1): constant coefficients in its box.
#pragma once

#include "media/volume_region.h"

namespace candela {

class HomogeneousVolume : public BoxRegion {
 public:
  using BoxRegion::BoxRegion;
  MediumPoint at(const Point3f& p, Float time) const override;
  // Beer's law in closed form: σt times the length of the ray inside the box.
  Spectrum opticalDepth(const Ray& ray, Float t0, Float t1, Float stepSize,
                        Float offset) const override;
  Spectrum majorant(const Ray& ray, Float t0, Float t1) const override;
  bool isHomogeneous() const override { return true; }
};

}  // namespace candela
