// pbrt-v3's "heterogeneous" named medium (pbrt 3e §11.3.4): σa and σs scaled by a density given
// on an nx × ny × nz grid of samples over the box [p0, p1] of the medium's coordinate system,
// trilinearly interpolated between sample points (which sit at cell centres) and zero outside
// the box; Henyey–Greenstein scattering with g. No closed form: integrators track through it
// with the majorant σt · max density.
#pragma once

#include <vector>

#include "core/transform.h"
#include "media/medium.h"

namespace candela {

class GridDensityMedium : public Medium {
 public:
  // density holds nx*ny*nz values, x fastest (index (z*ny + y)*nx + x), each >= 0; sigmaA and
  // sigmaS per unit of the medium's space at density 1 ("scale" already applied).
  GridDensityMedium(const Spectrum& sigmaA, const Spectrum& sigmaS, Float g, int nx, int ny, int nz,
                    std::vector<Float> density, const Point3f& p0, const Point3f& p1,
                    const Transform& mediumToWorld);
  // The interpolated density at a point of the unit cube [0,1]^3 that spans [p0, p1].
  Float density(const Point3f& pGrid) const;

  Bounds3f worldBound() const override { return worldBound_; }
  bool intersectP(const Ray& ray, Float* t0, Float* t1) const override;
  MediumPoint at(const Point3f& p, Float time) const override;
  PhaseFunction phase(const Point3f&, Float) const override { return phase_; }
  Spectrum majorant(const Ray&, Float, Float) const override { return sigmaT_ * maxDensity_; }

 private:
  Float sampleAt(int x, int y, int z) const;
  Point3f toGrid(const Point3f& pWorld) const;
  Spectrum sigmaA_, sigmaS_, sigmaT_;
  PhaseFunction phase_;
  int nx_, ny_, nz_;
  std::vector<Float> density_;
  Float maxDensity_ = 0;
  Bounds3f box_;  // [p0, p1] in medium space
  Transform worldToMedium_;
  Bounds3f worldBound_;
};

}  // namespace candela
