#include "lights/point_light.h"

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
