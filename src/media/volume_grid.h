// `Volume "volumegrid"` (lrt draft §12.3.2; pbrt 2e §11.3.2): density samples at the centres of
// nx × ny × nz cells filling the box, interpolated trilinearly (near the faces the outermost
// samples extend to the face); zero outside the box. density[(z·ny + y)·nx + x].
#pragma once

#include <vector>

#include "media/volume_region.h"

namespace candela {

class VolumeGrid : public DensityRegion {
 public:
  // density.size() == nx·ny·nz, every n >= 1 (checked by the factory).
  VolumeGrid(const Transform& volumeToWorld, const Bounds3f& extent,
             const RegionCoefficients& coefficients, int nx, int ny, int nz,
             std::vector<Float> density);
  Float density(const Point3f& pVolume) const override;
  // The largest sample of the cells that the segment's bounding box touches: the trilinear
  // interpolant never exceeds its corners.
  Spectrum majorant(const Ray& ray, Float t0, Float t1) const override;

 private:
  // The sample of cell (x, y, z), each index clamped to the grid on its own axis (the lrt
  // draft's listing clamps y and z with nx and indexes with z for x: not copied).
  Float sample(int x, int y, int z) const;
  // Continuous cell coordinates: cell i's centre is at i.
  Point3f cellCoordinates(const Point3f& pVolume) const;
  int n_[3];
  std::vector<Float> density_;
};

}  // namespace candela
