#include "lights/diffuse_area_light.h"

namespace candela {

Spectrum DiffuseAreaLight::sampleLi(const Interaction& ref, const Point2f& u, Vector3f* wi,
                                    Float* pdf, VisibilityTester* vis) const {
  Interaction pShape = shape_->sample(ref, u, pdf);
  Vector3f d = pShape.p - ref.p;
  if (*pdf == 0 || d.lengthSquared() == 0) {
    *pdf = 0;
    return Spectrum(0);
  }
  *wi = normalize(d);
  pShape.time = ref.time;
  vis->p0 = ref;
  vis->p1 = pShape;
  return L(pShape, -*wi);
}

}  // namespace candela
