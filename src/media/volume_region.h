// The volume regions of the lrt draft (ch. 12) and pbrt-v2 (pbrt 2e §11.3): a medium confined to
// an axis-aligned box [p0, p1] in the region's own coordinate system (the CTM at its `Volume`
// statement), vacuum outside. σa, σs and Le are per world unit of length; a density region
// scales them by a density function of the point in region space (lrt draft §12.3).
#pragma once

#include "core/transform.h"
#include "media/medium.h"

namespace candela {

// What every region has besides its extent: the coefficients (at density 1) and the phase.
struct RegionCoefficients {
  Spectrum sigmaA, sigmaS, Le;
  PhaseFunction phase;
};

// The parametric range [*t0, *t1] of ray (already in box space) inside box, within [tMin, tMax];
// false when it misses or the range is empty.
bool clipRayToBox(const Ray& ray, const Bounds3f& box, Float tMin, Float tMax, Float* t0,
                  Float* t1);

// A region bounded by a box in region space.
class BoxRegion : public Medium {
 public:
  BoxRegion(const Transform& volumeToWorld, const Bounds3f& extent,
            const RegionCoefficients& coefficients);
  Bounds3f worldBound() const override { return volumeToWorld_(extent_); }
  bool intersectP(const Ray& ray, Float* t0, Float* t1) const override;
  PhaseFunction phase(const Point3f&, Float) const override { return coefficients_.phase; }
  bool emits() const override { return !coefficients_.Le.isBlack(); }

 protected:
  // The part of [t0, t1] that lies in the box (false when none).
  bool clip(const Ray& ray, Float t0, Float t1, Float* c0, Float* c1) const;
  const Transform& worldToVolume() const { return worldToVolume_; }
  const Bounds3f& extent() const { return extent_; }
  const RegionCoefficients& coefficients() const { return coefficients_; }

 private:
  Transform volumeToWorld_, worldToVolume_;
  Bounds3f extent_;
  RegionCoefficients coefficients_;
};

// A region whose coefficients are density(p) times the given ones, p in region space (lrt draft
// §12.3's DensityRegion). Without a closed form its optical depth is ray-marched.
class DensityRegion : public BoxRegion {
 public:
  using BoxRegion::BoxRegion;
  // The density at pVolume (region space), only asked for points inside the extent.
  virtual Float density(const Point3f& pVolume) const = 0;
  MediumPoint at(const Point3f& p, Float time) const override;
  // Marches only the part of [t0, t1] inside the box.
  Spectrum opticalDepth(const Ray& ray, Float t0, Float t1, Float stepSize,
                        Float offset) const override;
};

}  // namespace candela
