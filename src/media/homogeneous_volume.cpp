#include "media/homogeneous_volume.h"

namespace candela {

MediumPoint HomogeneousVolume::at(const Point3f& p, Float) const {
  if (!extent().inside(worldToVolume()(p))) return {};
  const RegionCoefficients& c = coefficients();
  return {c.sigmaA, c.sigmaS, c.Le};
}

Spectrum HomogeneousVolume::opticalDepth(const Ray& ray, Float t0, Float t1, Float, Float) const {
  Float c0, c1;
  if (!clip(ray, t0, t1, &c0, &c1)) return Spectrum(0);
  const RegionCoefficients& c = coefficients();
  return (c.sigmaA + c.sigmaS) * ((c1 - c0) * ray.d.length());
}

Spectrum HomogeneousVolume::majorant(const Ray& ray, Float t0, Float t1) const {
  Float c0, c1;
  if (!clip(ray, t0, t1, &c0, &c1)) return Spectrum(0);
  return coefficients().sigmaA + coefficients().sigmaS;
}

}  // namespace candela
