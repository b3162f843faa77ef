// "directlighting": emitted plus directly reflected light, with Whitted-style recursion through
// specular reflection and transmission up to maxdepth (lrt draft §16.1; pbrt 2e §15.1).
#pragma once

#include "integrators/integrator.h"

namespace candela {

class DirectLightingIntegrator : public SurfaceIntegrator {
 public:
  enum class Strategy { All, One };
  DirectLightingIntegrator(Strategy strategy, int maxDepth)
      : strategy_(strategy), maxDepth_(maxDepth) {}
  Spectrum Li(const RayDifferential& ray, const Scene& scene, IntegratorContext& ctx,
              Float* alpha) const override;

 private:
  Spectrum trace(const RayDifferential& ray, const Scene& scene, IntegratorContext& ctx, int depth,
                 Float* alpha) const;
  Strategy strategy_;
  int maxDepth_;
};

}  // namespace candela
