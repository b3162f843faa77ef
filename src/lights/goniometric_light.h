// "goniometric": a point source at the light-space origin whose intensity over directions is a
// latitude-longitude image (lrt draft §13.2.3; inventory §16), I times the image's value.
//
// Axes: goniometric diagrams are drawn with y up, so the draft swaps y and z of the light-space
// direction before taking spherical angles: θ is measured from light-space +y (t = θ / π, the
// image's top row looking along +y) and φ = atan2(z, x) (s = φ / 2π). The image is looked up
// bilinearly at its finest level, clamped at the edges (no wrap across the poles).
#pragma once

#include <memory>

#include "core/transform.h"
#include "lights/light.h"
#include "textures/mipmap.h"

namespace candela {

class GoniometricLight : public Light {
 public:
  // image may be null: an isotropic source.
  GoniometricLight(const Transform& lightToWorld, const Spectrum& intensity,
                   std::shared_ptr<const MIPMap<Spectrum>> image);
  Spectrum sampleLi(const Interaction& ref, const Point2f& u, Vector3f* wi, Float* pdf,
                    VisibilityTester* vis) const override;
  Float pdfLi(const Interaction&, const Vector3f&) const override { return 0; }
  Spectrum sampleLe(const Point2f& uPos, const Point2f& uDir, Float time, Ray* ray,
                    Normal3f* nLight, Float* pdfPos, Float* pdfDir) const override;
  void pdfLe(const Ray& ray, const Normal3f& nLight, Float* pdfPos, Float* pdfDir) const override;
  // I times Σ texel × the solid angle of its (θ, φ) cell (exact for a constant image; pbrt-v2
  // takes 4π times the plain image mean, which ignores that rows near the poles cover less).
  Spectrum power() const override;
  bool isDelta() const override { return true; }
  // Its mean intensity (power / 4π) in every direction: the tree's estimate, not a bound.
  std::optional<LightBounds> bounds() const override {
    return pointSourceBounds(position_, power() / (4 * kPi));
  }
  // The image's value along a world-space direction leaving the light.
  Spectrum scale(const Vector3f& wWorld) const;

 private:
  Transform worldToLight_;
  Point3f position_;
  Spectrum intensity_;
  std::shared_ptr<const MIPMap<Spectrum>> image_;
};

}  // namespace candela
