// "projection": a slide projector at the light-space origin looking down +z (lrt draft §13.2.2;
// inventory §16). A direction leaving the light is projected through a perspective of the given
// fov onto the screen window; outside the window, or behind the near plane, nothing is emitted;
// inside, the intensity is I times the image looked up at the window position (1 with no image).
//
// Fixed defects of the draft (inventory §24): the projection uses the direction leaving the light
// (-wi), not the direction toward it, and the image aspect ratio is a floating-point division
// (the draft's integer division makes every landscape image square-ish and portraits aspect 0).
// The window is [-a, a] x [-1, 1] for aspect a > 1 and [-1, 1] x [-1/a, 1/a] otherwise, with the
// fov spanning the shorter side, as pbrt's perspective camera. As in pbrt-v2 and v3 (pbrt 3e
// §12.3.2: the image coordinates are the window position's offset from its lower corner), the
// image's top row is projected toward light-space -y: a camera at the projector with +y up sees
// the slide upside down, and scenes written for pbrt expect that.
#pragma once

#include <memory>

#include "core/transform.h"
#include "lights/light.h"
#include "textures/mipmap.h"

namespace candela {

class ProjectionLight : public Light {
 public:
  // image may be null (a constant 1 over the window); aspect is its width / height.
  ProjectionLight(const Transform& lightToWorld, const Spectrum& intensity, Float fovDeg,
                  std::shared_ptr<const MIPMap<Spectrum>> image, Float aspect);
  Spectrum sampleLi(const Interaction& ref, const Point2f& u, Vector3f* wi, Float* pdf,
                    VisibilityTester* vis) const override;
  Float pdfLi(const Interaction&, const Vector3f&) const override { return 0; }
  Spectrum sampleLe(const Point2f& uPos, const Point2f& uDir, Float time, Ray* ray,
                    Normal3f* nLight, Float* pdfPos, Float* pdfDir) const override;
  void pdfLe(const Ray& ray, const Normal3f& nLight, Float* pdfPos, Float* pdfDir) const override;
  // I times the image's mean times the exact solid angle of the rectangular pyramid,
  // 4 asin(sin α sin β) for half-angles α, β (pbrt-v2 uses the cone around the diagonal instead,
  // which overestimates). Exact for a constant image.
  Spectrum power() const override;
  bool isDelta() const override { return true; }
  // Its mean intensity over the window, within the cone that holds the window's pyramid.
  std::optional<LightBounds> bounds() const override;
  // The fraction of I (per channel) emitted along a world-space direction leaving the light.
  Spectrum projection(const Vector3f& wWorld) const;

 private:
  // Solid-angle density of sampleLe's directions (uniform over the window), 0 outside it.
  Float directionPdf(const Vector3f& wWorld) const;

  Transform lightToWorld_, worldToLight_;
  Point3f position_;
  Spectrum intensity_;
  std::shared_ptr<const MIPMap<Spectrum>> image_;
  Float tanHalfFov_;
  Float screenX_, screenY_;  // the window is [-screenX_, screenX_] x [-screenY_, screenY_]
};

}  // namespace candela
