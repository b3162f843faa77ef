// "area"/"diffuse": uniform emitted radiance L from one side of a shape, or both when twosided
// (lrt draft §13.4).
#pragma once

#include "lights/light.h"
#include "shapes/shape.h"

namespace candela {

// final: its own calls of L (each light sample) are direct, not through the vtable.
class DiffuseAreaLight final : public AreaLight {
 public:
  DiffuseAreaLight(const Shape* shape, const Spectrum& lEmit, int nSamples, bool twoSided)
      : AreaLight(nSamples), shape_(shape), lEmit_(lEmit), twoSided_(twoSided) {}
  Spectrum L(const Interaction& it, const Vector3f& w) const override {
    return (twoSided_ || dot(it.n, w) > 0) ? lEmit_ : Spectrum(0);
  }
  Spectrum sampleLi(const Interaction& ref, const Point2f& u, Vector3f* wi, Float* pdf,
                    VisibilityTester* vis) const override;
  Float pdfLi(const Interaction& ref, const Vector3f& wi) const override {
    return shape_->pdf(ref, wi);
  }
  Spectrum sampleLe(const Point2f& uPos, const Point2f& uDir, Float time, Ray* ray,
                    Normal3f* nLight, Float* pdfPos, Float* pdfDir) const override;
  void pdfLe(const Ray& ray, const Normal3f& nLight, Float* pdfPos, Float* pdfDir) const override;
  Spectrum power() const override { return lEmit_ * ((twoSided_ ? 2 : 1) * shape_->area() * kPi); }
  bool isDelta() const override { return false; }
  // The shape's bounds and normal cone; its largest intensity is L times its area, along the
  // normal.
  std::optional<LightBounds> bounds() const override;

 private:
  const Shape* shape_;
  Spectrum lEmit_;
  bool twoSided_;
};

}  // namespace candela
