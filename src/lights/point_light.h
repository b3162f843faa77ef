// "point": isotropic point source of intensity I at `from` (lrt draft §13.2).
#pragma once

#include "core/transform.h"
#include "lights/light.h"

namespace candela {

class PointLight : public Light {
 public:
  PointLight(const Transform& lightToWorld, const Spectrum& intensity, const Point3f& from)
      : position_(lightToWorld(from)), intensity_(intensity) {}
  Spectrum sampleLi(const Interaction& ref, const Point2f& u, Vector3f* wi, Float* pdf,
                    VisibilityTester* vis) const override;
  Float pdfLi(const Interaction&, const Vector3f&) const override { return 0; }
  Spectrum sampleLe(const Point2f& uPos, const Point2f& uDir, Float time, Ray* ray,
                    Normal3f* nLight, Float* pdfPos, Float* pdfDir) const override;
  void pdfLe(const Ray& ray, const Normal3f& nLight, Float* pdfPos, Float* pdfDir) const override;
  Spectrum power() const override { return intensity_ * (4 * kPi); }
  bool isDelta() const override { return true; }
  std::optional<LightBounds> bounds() const override {
    return pointSourceBounds(position_, intensity_);
  }
  const Point3f& position() const { return position_; }

 private:
  Point3f position_;
  Spectrum intensity_;
};

}  // namespace candela
