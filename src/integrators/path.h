// "path": unidirectional path tracing with next-event estimation, MIS by the power heuristic and
// Russian roulette (pbrt 2e §15.3). maxdepth bounds the number of scattering events, so a path
// of maxdepth d carries emission seen directly plus up to d reflections.
#pragma once

#include "integrators/integrator.h"

namespace candela {

class PathIntegrator : public SurfaceIntegrator {
 public:
  explicit PathIntegrator(int maxDepth, int rrStartDepth = 3)
      : maxDepth_(maxDepth), rrStartDepth_(rrStartDepth) {}
  Spectrum Li(const RayDifferential& ray, const Scene& scene, IntegratorContext& ctx,
              Float* alpha) const override;

 private:
  int maxDepth_;
  int rrStartDepth_;
};

}  // namespace candela
