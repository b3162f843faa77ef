#include "media/grid_density_medium.h"

#include <algorithm>
#include <cmath>

namespace candela {

GridDensityMedium::GridDensityMedium(const Spectrum& sigmaA, const Spectrum& sigmaS, Float g,
                                     int nx, int ny, int nz, std::vector<Float> density,
                                     const Point3f& p0, const Point3f& p1,
                                     const Transform& mediumToWorld)
    : sigmaA_(sigmaA),
      sigmaS_(sigmaS),
      sigmaT_(sigmaA + sigmaS),
      phase_(PhaseFunction::henyeyGreenstein(g)),
      nx_(nx),
      ny_(ny),
      nz_(nz),
      density_(std::move(density)),
      box_(p0, p1),
      worldToMedium_(inverse(mediumToWorld)),
      worldBound_(mediumToWorld(Bounds3f(p0, p1))) {
  for (Float d : density_) maxDensity_ = std::max(maxDensity_, d);
}

Float GridDensityMedium::sampleAt(int x, int y, int z) const {
  if (x < 0 || y < 0 || z < 0 || x >= nx_ || y >= ny_ || z >= nz_) return 0;
  return density_[(size_t(z) * size_t(ny_) + size_t(y)) * size_t(nx_) + size_t(x)];
}

Float GridDensityMedium::density(const Point3f& pGrid) const {
  // Sample (x, y, z) sits at the centre of its cell, ((x + 1/2)/nx, ...) (pbrt 3e §11.3.4).
  Float sx = pGrid.x * Float(nx_) - 0.5f, sy = pGrid.y * Float(ny_) - 0.5f,
        sz = pGrid.z * Float(nz_) - 0.5f;
  Float fx = std::floor(sx), fy = std::floor(sy), fz = std::floor(sz);
  // Far outside, the integer conversion would overflow; every neighbour is outside anyway.
  if (!(fx >= -2 && fy >= -2 && fz >= -2 && fx <= Float(nx_) && fy <= Float(ny_) &&
        fz <= Float(nz_)))
    return 0;
  int ix = int(fx), iy = int(fy), iz = int(fz);
  Float dx = sx - fx, dy = sy - fy, dz = sz - fz;
  auto lerpX = [&](int y, int z) { return lerp(dx, sampleAt(ix, y, z), sampleAt(ix + 1, y, z)); };
  Float d00 = lerpX(iy, iz), d10 = lerpX(iy + 1, iz), d01 = lerpX(iy, iz + 1),
        d11 = lerpX(iy + 1, iz + 1);
  return lerp(dz, lerp(dy, d00, d10), lerp(dy, d01, d11));
}

Point3f GridDensityMedium::toGrid(const Point3f& pWorld) const {
  Point3f p = worldToMedium_(pWorld);
  Vector3f extent = box_.diagonal();
  return Point3f((p.x - box_.pMin.x) / extent.x, (p.y - box_.pMin.y) / extent.y,
                 (p.z - box_.pMin.z) / extent.z);
}

MediumPoint GridDensityMedium::at(const Point3f& p, Float) const {
  Float d = density(toGrid(p));
  return {sigmaA_ * d, sigmaS_ * d, Spectrum(0)};
}

bool GridDensityMedium::intersectP(const Ray& rayWorld, Float* t0, Float* t1) const {
  // Slabs in the medium's space, where the box is axis-aligned; an affine map keeps t.
  Ray ray(worldToMedium_(rayWorld.o), worldToMedium_(rayWorld.d));
  Float lo = 0, hi = rayWorld.tMax;
  for (int axis = 0; axis < 3; ++axis) {
    Float o = axis == 0 ? ray.o.x : axis == 1 ? ray.o.y : ray.o.z;
    Float d = axis == 0 ? ray.d.x : axis == 1 ? ray.d.y : ray.d.z;
    Float bMin = axis == 0 ? box_.pMin.x : axis == 1 ? box_.pMin.y : box_.pMin.z;
    Float bMax = axis == 0 ? box_.pMax.x : axis == 1 ? box_.pMax.y : box_.pMax.z;
    if (d == 0) {
      if (o < bMin || o > bMax) return false;
      continue;
    }
    Float tNear = (bMin - o) / d, tFar = (bMax - o) / d;
    if (tNear > tFar) std::swap(tNear, tFar);
    lo = std::max(lo, tNear);
    hi = std::min(hi, tFar);
    if (lo > hi) return false;
  }
  *t0 = lo;
  *t1 = hi;
  return true;
}

}  // namespace candela
