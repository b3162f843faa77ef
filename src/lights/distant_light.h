// "distant": parallel light of radiance-like strength L (irradiance L at normal incidence)
// arriving along from -> to (lrt draft §13.3; inventory §16). wi, the direction toward the light,
// is normalize(from - to) carried to world space.
#pragma once

#include "core/transform.h"
#include "lights/light.h"

namespace candela {

class DistantLight : public Light {
 public:
  DistantLight(const Transform& lightToWorld, const Spectrum& radiance, const Point3f& from,
               const Point3f& to);
  Spectrum sampleLi(const Interaction& ref, const Point2f& u, Vector3f* wi, Float* pdf,
                    VisibilityTester* vis) const override;
  Float pdfLi(const Interaction&, const Vector3f&) const override { return 0; }
  Spectrum sampleLe(const Point2f& uPos, const Point2f& uDir, Float time, Ray* ray,
                    Normal3f* nLight, Float* pdfPos, Float* pdfDir) const override;
  void pdfLe(const Ray& ray, const Normal3f& nLight, Float* pdfPos, Float* pdfDir) const override;
  // What crosses the scene's bounding disk: L π R² (R from preprocess).
  Spectrum power() const override { return radiance_ * (kPi * sceneRadius_ * sceneRadius_); }
  bool isDelta() const override { return true; }
  bool atInfinity() const override { return true; }
  void preprocess(const Bounds3f& sceneBounds) override;
  const Vector3f& direction() const { return wLight_; }

 private:
  Vector3f wLight_;  // unit, toward the light
  Spectrum radiance_;
  Point3f sceneCenter_{0, 0, 0};
  // Until preprocess: large enough that a shadow ray reaches past any test geometry.
  Float sceneRadius_ = 1e4f;
};

}  // namespace candela
