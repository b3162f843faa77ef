#include "media/volume_grid.h"

#include <algorithm>
#include <cmath>

namespace candela {

VolumeGrid::VolumeGrid(const Transform& volumeToWorld, const Bounds3f& extent,
                       const RegionCoefficients& coefficients, int nx, int ny, int nz,
                       std::vector<Float> density)
    : DensityRegion(volumeToWorld, extent, coefficients),
      n_{nx, ny, nz},
      density_(std::move(density)) {}

Float VolumeGrid::sample(int x, int y, int z) const {
  x = std::clamp(x, 0, n_[0] - 1);
  y = std::clamp(y, 0, n_[1] - 1);
  z = std::clamp(z, 0, n_[2] - 1);
  return density_[(size_t(z) * size_t(n_[1]) + size_t(y)) * size_t(n_[0]) + size_t(x)];
}

Point3f VolumeGrid::cellCoordinates(const Point3f& pVolume) const {
  const Bounds3f& b = extent();
  Point3f c;
  for (int a = 0; a < 3; ++a) {
    Float u = (pVolume[a] - b.pMin[a]) / (b.pMax[a] - b.pMin[a]);
    c[a] = u * Float(n_[a]) - Float(0.5);
  }
  return c;
}

Float VolumeGrid::density(const Point3f& pVolume) const {
  if (!extent().inside(pVolume)) return 0;
  Point3f c = cellCoordinates(pVolume);
  int x = int(std::floor(c.x)), y = int(std::floor(c.y)), z = int(std::floor(c.z));
  Float fx = c.x - Float(x), fy = c.y - Float(y), fz = c.z - Float(z);
  auto lerp = [](Float t, Float a, Float b) { return (1 - t) * a + t * b; };
  Float d00 = lerp(fx, sample(x, y, z), sample(x + 1, y, z));
  Float d10 = lerp(fx, sample(x, y + 1, z), sample(x + 1, y + 1, z));
  Float d01 = lerp(fx, sample(x, y, z + 1), sample(x + 1, y, z + 1));
  Float d11 = lerp(fx, sample(x, y + 1, z + 1), sample(x + 1, y + 1, z + 1));
  return lerp(fz, lerp(fy, d00, d10), lerp(fy, d01, d11));
}

Spectrum VolumeGrid::majorant(const Ray& ray, Float t0, Float t1) const {
  Float c0, c1;
  if (!clip(ray, t0, t1, &c0, &c1)) return Spectrum(0);
  Point3f a = cellCoordinates(worldToVolume()(ray(c0)));
  Point3f b = cellCoordinates(worldToVolume()(ray(c1)));
  int lo[3], hi[3];
  for (int k = 0; k < 3; ++k) {
    Float mn = std::min(a[k], b[k]), mx = std::max(a[k], b[k]);
    lo[k] = std::clamp(int(std::floor(mn)), 0, n_[k] - 1);
    hi[k] = std::clamp(int(std::floor(mx)) + 1, 0, n_[k] - 1);
  }
  Float m = 0;
  for (int z = lo[2]; z <= hi[2]; ++z)
    for (int y = lo[1]; y <= hi[1]; ++y)
      for (int x = lo[0]; x <= hi[0]; ++x) m = std::max(m, sample(x, y, z));
  const RegionCoefficients& c = coefficients();
  return (c.sigmaA + c.sigmaS) * m;
}

}  // namespace candela
