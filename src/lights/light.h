// Light sources (lrt draft ch. 13, sampling §15.4). sampleLi returns incident radiance (intensity
// / r^2 for delta lights) toward ref, with the solid-angle pdf of the sampled direction.
//
// sampleLe starts a light subpath (pbrt 3e §12/§16.1; the draft's Sample_L(scene, u1..u4, ray,
// pdf)): it returns the emitted radiance (intensity for point-like sources) along the ray. A delta
// component (the position of a point source, the direction of a distant one) reports density 1,
// the Dirac measured against itself, and pdfLe reports the same, so the two always agree;
// integrators tell delta lights apart with isDelta().
#pragma once

#include <optional>

#include "accel/aggregate.h"
#include "core/interaction.h"
#include "core/spectrum.h"
#include "lights/light_bounds.h"

namespace candela {

// The segment between a shading point and a light sample; occlusion is asked of the aggregate.
struct VisibilityTester {
  Interaction p0, p1;
  bool unoccluded(const Aggregate& aggregate) const {
    return !aggregate.intersectP(p0.spawnRayTo(p1));
  }
};

class Light {
 public:
  explicit Light(int nSamples = 1) : nSamples_(std::max(1, nSamples)) {}
  virtual ~Light() = default;
  virtual Spectrum sampleLi(const Interaction& ref, const Point2f& u, Vector3f* wi, Float* pdf,
                            VisibilityTester* vis) const = 0;
  virtual Float pdfLi(const Interaction& ref, const Vector3f& wi) const = 0;
  // A ray leaving the light: origin density per area (pdfPos; for distant and infinite lights per
  // area of the disk that covers the scene) and direction density per solid angle (pdfDir).
  virtual Spectrum sampleLe(const Point2f& uPos, const Point2f& uDir, Float time, Ray* ray,
                            Normal3f* nLight, Float* pdfPos, Float* pdfDir) const = 0;
  virtual void pdfLe(const Ray& ray, const Normal3f& nLight, Float* pdfPos,
                     Float* pdfDir) const = 0;
  virtual Spectrum power() const = 0;
  virtual bool isDelta() const = 0;
  // Distant and infinite lights: no position, light arriving from directions at infinity.
  virtual bool atInfinity() const { return false; }
  // Radiance along a ray that escapes the scene (infinite lights).
  virtual Spectrum Le(const RayDifferential&) const { return Spectrum(0); }
  virtual void preprocess(const Bounds3f& /*sceneBounds*/) {}
  // Where the light is and how strongly and which way it shines, for the light tree (see
  // LightBounds); none for lights at infinity, which it samples beside the tree.
  virtual std::optional<LightBounds> bounds() const { return std::nullopt; }
  int nSamples() const { return nSamples_; }

 private:
  int nSamples_;
};

// A light attached to a shape: emits L(p, n, w) from its surface.
class AreaLight : public Light {
 public:
  using Light::Light;
  virtual Spectrum L(const Interaction& it, const Vector3f& w) const = 0;
};

}  // namespace candela
