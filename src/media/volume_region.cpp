#include "media/volume_region.h"

#include <algorithm>
#include <cmath>

namespace candela {

bool clipRayToBox(const Ray& ray, const Bounds3f& box, Float tMin, Float tMax, Float* t0,
                  Float* t1) {
  // Slabs (lrt draft §4.2.1): each axis narrows [tMin, tMax]; a direction parallel to an axis
  // gives infinite slab distances, and a NaN (origin on a face) leaves the range unchanged.
  for (int a = 0; a < 3; ++a) {
    Float inv = 1 / ray.d[a];
    Float tNear = (box.pMin[a] - ray.o[a]) * inv;
    Float tFar = (box.pMax[a] - ray.o[a]) * inv;
    if (tNear > tFar) std::swap(tNear, tFar);
    if (tNear > tMin) tMin = tNear;
    if (tFar < tMax) tMax = tFar;
    if (tMin > tMax) return false;
  }
  if (!(tMax > tMin)) return false;
  *t0 = tMin;
  *t1 = tMax;
  return true;
}

BoxRegion::BoxRegion(const Transform& volumeToWorld, const Bounds3f& extent,
                     const RegionCoefficients& coefficients)
    : volumeToWorld_(volumeToWorld),
      worldToVolume_(inverse(volumeToWorld)),
      extent_(extent),
      coefficients_(coefficients) {}

bool BoxRegion::intersectP(const Ray& ray, Float* t0, Float* t1) const {
  return clip(ray, 0, ray.tMax, t0, t1);
}

bool BoxRegion::clip(const Ray& ray, Float t0, Float t1, Float* c0, Float* c1) const {
  // The region-space ray at the same t (the transform is affine; no origin offset here).
  Ray r(worldToVolume_(ray.o), worldToVolume_(ray.d), ray.tMax, ray.time);
  return clipRayToBox(r, extent_, t0, t1, c0, c1);
}

MediumPoint DensityRegion::at(const Point3f& p, Float) const {
  Point3f pv = worldToVolume()(p);
  if (!extent().inside(pv)) return {};
  Float d = density(pv);
  const RegionCoefficients& c = coefficients();
  return {c.sigmaA * d, c.sigmaS * d, c.Le * d};
}

Spectrum DensityRegion::opticalDepth(const Ray& ray, Float t0, Float t1, Float stepSize,
                                     Float offset) const {
  Float c0, c1;
  if (!clip(ray, t0, t1, &c0, &c1)) return Spectrum(0);
  return Medium::opticalDepth(ray, c0, c1, stepSize, offset);
}

}  // namespace candela
