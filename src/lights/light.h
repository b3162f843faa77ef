// Light sources (lrt draft ch. 13, sampling §15.4). sampleLi returns incident radiance (intensity
// / r^2 for delta lights) toward ref, with the solid-angle pdf of the sampled direction.
#pragma once

#include "accel/aggregate.h"
#include "core/interaction.h"
#include "core/spectrum.h"

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
  virtual Spectrum power() const = 0;
  virtual bool isDelta() const = 0;
  // Radiance along a ray that escapes the scene (infinite lights).
  virtual Spectrum Le(const RayDifferential&) const { return Spectrum(0); }
  virtual void preprocess(const Bounds3f& /*sceneBounds*/) {}
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
