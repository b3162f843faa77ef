#include "media/homogeneous_medium.h"

namespace candela {

HomogeneousMedium::HomogeneousMedium(const Spectrum& sigmaA, const Spectrum& sigmaS, Float g)
    : sigmaA_(sigmaA), sigmaS_(sigmaS), phase_(PhaseFunction::henyeyGreenstein(g)) {}

Bounds3f HomogeneousMedium::worldBound() const {
  return Bounds3f(Point3f(-kInfinity, -kInfinity, -kInfinity),
                  Point3f(kInfinity, kInfinity, kInfinity));
}

bool HomogeneousMedium::intersectP(const Ray& ray, Float* t0, Float* t1) const {
  *t0 = 0;
  *t1 = ray.tMax;
  return true;
}

Spectrum HomogeneousMedium::opticalDepth(const Ray& ray, Float t0, Float t1, Float, Float) const {
  Float length = (t1 - t0) * ray.d.length();
  if (!(length > 0)) return Spectrum(0);
  return (sigmaA_ + sigmaS_) * length;
}

}  // namespace candela
