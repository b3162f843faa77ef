// `Volume "exponential"` (lrt draft §12.3.1; pbrt 2e §11.3.3): density a·exp(-b·h), h the height
// of the region-space point above the box's corner p0 along the unit vector updir, e.g. the
// thinning of an atmosphere with altitude.
#pragma once

#include "media/volume_region.h"

namespace candela {

class ExponentialVolume : public DensityRegion {
 public:
  // up: any nonzero vector (normalised here).
  ExponentialVolume(const Transform& volumeToWorld, const Bounds3f& extent,
                    const RegionCoefficients& coefficients, Float a, Float b, const Vector3f& up);
  Float density(const Point3f& pVolume) const override;
  // In closed form (the lrt draft's exercise 12.1): along the ray h is linear in t, so the
  // density is exp(-b·(h0 + k·t)), whose integral is elementary.
  Spectrum opticalDepth(const Ray& ray, Float t0, Float t1, Float stepSize,
                        Float offset) const override;
  // The density is monotonic along a ray: its larger end value.
  Spectrum majorant(const Ray& ray, Float t0, Float t1) const override;

 private:
  Float a_, b_;
  Vector3f up_;
};

}  // namespace candela
