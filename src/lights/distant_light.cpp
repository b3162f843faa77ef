#include "lights/distant_light.h"

#include "core/sampling.h"

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

namespace candela {

// The origin is uniform on the disk of the scene's bounding radius R, facing the light, one R
// beyond the centre; every ray crosses the scene in the light's one direction (pbrt 3e §16.1).
Spectrum DistantLight::sampleLe(const Point2f& uPos, const Point2f&, Float time, Ray* ray,
                                Normal3f* nLight, Float* pdfPos, Float* pdfDir) const {
  Vector3f v1, v2;
  coordinateSystem(wLight_, &v1, &v2);
  Point2f c = sampleUniformDiskConcentric(uPos);
  Point3f o = sceneCenter_ + (wLight_ + v1 * c.x + v2 * c.y) * sceneRadius_;
  *ray = Ray(o, -wLight_, kInfinity, time);
  *nLight = Normal3f(-wLight_.x, -wLight_.y, -wLight_.z);
  *pdfPos = 1 / (kPi * sceneRadius_ * sceneRadius_);
  *pdfDir = 1;
  return radiance_;
}

void DistantLight::pdfLe(const Ray&, const Normal3f&, Float* pdfPos, Float* pdfDir) const {
  *pdfPos = 1 / (kPi * sceneRadius_ * sceneRadius_);
  *pdfDir = 1;
}

}  // namespace candela
