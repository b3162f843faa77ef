#include "media/exponential_volume.h"

#include <cmath>

namespace candela {

ExponentialVolume::ExponentialVolume(const Transform& volumeToWorld, const Bounds3f& extent,
                                     const RegionCoefficients& coefficients, Float a, Float b,
                                     const Vector3f& up)
    : DensityRegion(volumeToWorld, extent, coefficients), a_(a), b_(b), up_(normalize(up)) {}

Float ExponentialVolume::density(const Point3f& pVolume) const {
  Float h = dot(pVolume - extent().pMin, up_);
  return a_ * std::exp(-b_ * h);
}

Spectrum ExponentialVolume::opticalDepth(const Ray& ray, Float t0, Float t1, Float, Float) const {
  Float c0, c1;
  if (!clip(ray, t0, t1, &c0, &c1)) return Spectrum(0);
  // h(t) = h(c0) + k·(t - c0) in region space; the density is per world length |d| dt.
  Point3f o = worldToVolume()(ray(c0));
  Vector3f d = worldToVolume()(ray.d);
  double h0 = dot(o - extent().pMin, up_);
  double k = dot(d, up_);
  double span = double(c1) - double(c0);
  double x = double(b_) * k * span;
  // ∫_0^span exp(-b (h0 + k s)) ds = exp(-b h0) · span · (1 - e^{-x}) / x, → span as x → 0.
  double shape = std::abs(x) < 1e-8 ? 1 - x / 2 : -std::expm1(-x) / x;
  double integral = double(a_) * std::exp(-double(b_) * h0) * span * shape;
  const RegionCoefficients& c = coefficients();
  return (c.sigmaA + c.sigmaS) * Float(integral * double(ray.d.length()));
}

Spectrum ExponentialVolume::majorant(const Ray& ray, Float t0, Float t1) const {
  Float c0, c1;
  if (!clip(ray, t0, t1, &c0, &c1)) return Spectrum(0);
  Float d0 = density(worldToVolume()(ray(c0))), d1 = density(worldToVolume()(ray(c1)));
  const RegionCoefficients& c = coefficients();
  return (c.sigmaA + c.sigmaS) * std::max(d0, d1);
}

}  // namespace candela
