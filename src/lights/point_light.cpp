#include "lights/point_light.h"

#include "core/sampling.h"

namespace candela {

Spectrum PointLight::sampleLi(const Interaction& ref, const Point2f&, Vector3f* wi, Float* pdf,
                              VisibilityTester* vis) const {
  Vector3f d = position_ - ref.p;
  Float dist2 = d.lengthSquared();
  if (dist2 == 0) {
    *pdf = 0;
    return Spectrum(0);
  }
  *wi = d / std::sqrt(dist2);
  *pdf = 1;
  vis->p0 = ref;
  vis->p1 = Interaction(position_, ref.time);
  return intensity_ / dist2;
}

}  // namespace candela

namespace candela {

// Uniform directions over the sphere from the fixed position (pbrt 3e §16.1).
Spectrum PointLight::sampleLe(const Point2f&, const Point2f& uDir, Float time, Ray* ray,
                              Normal3f* nLight, Float* pdfPos, Float* pdfDir) const {
  Vector3f d = sampleUniformSphere(uDir);
  *ray = Ray(position_, d, kInfinity, time);
  *nLight = Normal3f(d.x, d.y, d.z);
  *pdfPos = 1;
  *pdfDir = uniformSpherePdf();
  return intensity_;
}

void PointLight::pdfLe(const Ray&, const Normal3f&, Float* pdfPos, Float* pdfDir) const {
  *pdfPos = 1;
  *pdfDir = uniformSpherePdf();
}

}  // namespace candela
