#include "lights/distant_light.h"

namespace candela {

DistantLight::DistantLight(const Transform& lightToWorld, const Spectrum& radiance,
                           const Point3f& from, const Point3f& to)
    : radiance_(radiance) {
  Vector3f w = lightToWorld(from - to);
  wLight_ = w.lengthSquared() > 0 ? normalize(w) : Vector3f(0, 0, -1);
}

void DistantLight::preprocess(const Bounds3f& sceneBounds) {
  Point3f c;
  Float r;
  sceneBounds.boundingSphere(&c, &r);
  sceneCenter_ = c;
  sceneRadius_ = r;
}

Spectrum DistantLight::sampleLi(const Interaction& ref, const Point2f&, Vector3f* wi, Float* pdf,
                                VisibilityTester* vis) const {
  *wi = wLight_;
  *pdf = 1;
  // A point beyond the scene's bounding sphere along wi: the shadow ray crosses all geometry.
  Float reach = 2 * sceneRadius_ + distance(ref.p, sceneCenter_);
  vis->p0 = ref;
  vis->p1 = Interaction(ref.p + wLight_ * reach, ref.time);
  return radiance_;
}

}  // namespace candela
