// The ray-tracing skeleton that "whitted" and "directlighting" share (pbrt 2e §1.3.6, §15.1;
// lrt draft ch. 1): emission seen at the hit, light arriving directly from the light sources
// (each subclass estimates it its own way), and recursion through perfect specular reflection
// and transmission while depth + 1 < maxdepth. Rays that escape see the lights' Le.
#pragma once

#include <functional>

#include "integrators/pixel_sample_integrator.h"
#include "reflection/bsdf.h"

namespace candela {

class SpecularRecursionIntegrator : public PixelSampleIntegrator {
 public:
  explicit SpecularRecursionIntegrator(int maxDepth) : maxDepth_(maxDepth) {}
  Spectrum Li(const RayDifferential& ray, const Scene& scene, IntegratorContext& ctx,
              Float* alpha) const final;
  int maxDepth() const { return maxDepth_; }

 protected:
  // Radiance reflected at isect toward isect.wo straight from the lights.
  virtual Spectrum directLight(const SurfaceInteraction& isect, const BSDF& bsdf,
                               const Scene& scene, IntegratorContext& ctx) const = 0;

  // The same walk with another term at each scattering surface in place of directLight (the
  // irradiance cache's prepass visits the points a camera ray shades through it).
  using SurfaceTerm =
      std::function<Spectrum(const SurfaceInteraction&, const BSDF&, IntegratorContext&)>;
  Spectrum traceWith(const RayDifferential& ray, const Scene& scene, IntegratorContext& ctx,
                     const SurfaceTerm& term) const;

 private:
  Spectrum trace(const RayDifferential& ray, const Scene& scene, IntegratorContext& ctx, int depth,
                 Float* alpha, const SurfaceTerm* term) const;
  int maxDepth_;
};

}  // namespace candela
