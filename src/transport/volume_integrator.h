// Volume integrators (lrt draft §16.7; pbrt 2e §16.2): the light that the scene's volume
// (Scene::volume(), pbrt-v2's `Volume` regions) adds along a ray and the fraction of the light
// behind it that gets through. The pixel-sample loop combines them with an integrator's
// radiance as L = T·L_surface + L_volume (the draft's Scene::L), and only in scenes that have a
// volume.
//
// Both integrators march the ray in equal steps of at most stepsize (world units), the first
// step at a random fraction of a step drawn from the sampler, so that the sum is an unbiased
// estimate of the integral over the random offset (lrt draft §16.7.1).
#pragma once

#include "transport/integrator_context.h"

namespace candela {

class RNG;

class VolumeIntegrator {
 public:
  explicit VolumeIntegrator(Float stepSize) : stepSize_(stepSize) {}
  virtual ~VolumeIntegrator() = default;
  // Radiance added by the volume along ray between its origin and ray.tMax (a surface hit, or
  // infinity), toward the origin; *transmittance: the fraction of radiance leaving ray(ray.tMax)
  // toward the origin that arrives there.
  Spectrum Li(const Ray& ray, const Scene& scene, IntegratorContext& ctx,
              Spectrum* transmittance) const;
  // The transmittance of the segment [0, ray.tMax] (shadow rays, path segments), ray-marched
  // with 4 x stepsize where the medium has no closed form (the draft's EmissionIntegrator).
  Spectrum transmittance(const Ray& ray, const Scene& scene, IntegratorContext& ctx) const;
  Float stepSize() const { return stepSize_; }

 protected:
  // Whether the source term can be nonzero anywhere in medium (else Li only computes T).
  virtual bool hasSource(const Medium& medium) const = 0;
  // The source term at p: radiance per unit length that the volume emits and scatters at p
  // toward wo (unit, pointing back to the ray's origin), m being the coefficients there.
  virtual Spectrum source(const Point3f& p, Float time, const MediumPoint& m, const Vector3f& wo,
                          const Scene& scene, IntegratorContext& ctx, RNG& rng) const = 0;

 private:
  Float stepSize_;
};

// pbrt-v2's default: emission only (`VolumeIntegrator "emission"`).
class EmissionIntegrator : public VolumeIntegrator {
 public:
  using VolumeIntegrator::VolumeIntegrator;

 protected:
  bool hasSource(const Medium& medium) const override { return medium.emits(); }
  Spectrum source(const Point3f&, Float, const MediumPoint& m, const Vector3f&, const Scene&,
                  IntegratorContext&, RNG&) const override {
    return m.Le;
  }
};

// Single scattering (`VolumeIntegrator "single"`, lrt draft §16.7.2): emission plus light that
// arrives straight from one light source, chosen uniformly at each step, and scatters once
// toward the ray's origin; its shadow ray is attenuated by the volume too.
class SingleScatteringIntegrator : public VolumeIntegrator {
 public:
  using VolumeIntegrator::VolumeIntegrator;

 protected:
  bool hasSource(const Medium&) const override { return true; }
  Spectrum source(const Point3f& p, Float time, const MediumPoint& m, const Vector3f& wo,
                  const Scene& scene, IntegratorContext& ctx, RNG& rng) const override;
};

}  // namespace candela
