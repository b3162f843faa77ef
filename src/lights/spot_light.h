// "spot": a point source at `from` shining toward `to` with a cone of half-angle coneangle whose
// edge fades over conedeltaangle (lrt draft §13.2.1; inventory §16). Intensity is I inside the
// inner cone (cos > cosFalloffStart), 0 outside the outer cone (cos < cosTotalWidth), and I δ⁴ in
// between, δ = (cos - cosTotalWidth) / (cosFalloffStart - cosTotalWidth).
//
// The falloff is evaluated for the direction leaving the light toward the lit point (-wi); the
// draft passes the direction toward the light (inventory §24), which would light only the points
// behind the spot.
#pragma once

#include "core/transform.h"
#include "lights/light.h"

namespace candela {

class SpotLight : public Light {
 public:
  // coneAngle and coneDelta in degrees; the cone's axis runs from `from` to `to` in light space.
  SpotLight(const Transform& lightToWorld, const Spectrum& intensity, const Point3f& from,
            const Point3f& to, Float coneAngle, Float coneDelta);
  Spectrum sampleLi(const Interaction& ref, const Point2f& u, Vector3f* wi, Float* pdf,
                    VisibilityTester* vis) const override;
  Float pdfLi(const Interaction&, const Vector3f&) const override { return 0; }
  Spectrum sampleLe(const Point2f& uPos, const Point2f& uDir, Float time, Ray* ray,
                    Normal3f* nLight, Float* pdfPos, Float* pdfDir) const override;
  void pdfLe(const Ray& ray, const Normal3f& nLight, Float* pdfPos, Float* pdfDir) const override;
  // The exact integral of the intensity over the sphere: 2π I ((1 - cosFalloffStart) +
  // (cosFalloffStart - cosTotalWidth) / 5), the 1/5 being ∫δ⁴ over the falloff band. (pbrt-v2
  // uses 1/2 there, i.e. a linear falloff; the two differ by 0.3 (cosF - cosW) 2π I.)
  Spectrum power() const override;
  bool isDelta() const override { return true; }
  // Its full intensity out to the inner cone, nothing past the outer one.
  std::optional<LightBounds> bounds() const override;
  // The fraction of I emitted along a world-space direction leaving the light.
  Float falloff(const Vector3f& wWorld) const;
  const Point3f& position() const { return position_; }

 private:
  Transform lightToWorld_, worldToLight_;  // the cone's axis is +z in light space
  Point3f position_;
  Spectrum intensity_;
  Float cosTotalWidth_, cosFalloffStart_;
};

}  // namespace candela
