// "path": unidirectional path tracing with next-event estimation, MIS by the power heuristic and
// Russian roulette (pbrt 2e §15.3). maxdepth bounds the number of scattering events, so a path
// of maxdepth d carries emission seen directly plus up to d reflections. Each vertex traces one
// shadow ray and one ray onward: the BSDF's sample that continues the path is also the BSDF
// strategy of the light's MIS (pbrt 4e §13.4), where pbrt 2e traces a third ray for it.
#pragma once

#include "integrators/integrator.h"

namespace candela {

class PathIntegrator : public SurfaceIntegrator {
 public:
  bool attenuatesEveryRay() const override { return true; }
  explicit PathIntegrator(int maxDepth, int rrStartDepth = 3)
      : maxDepth_(maxDepth), rrStartDepth_(rrStartDepth) {}
  int maxDepth() const { return maxDepth_; }
  Spectrum Li(const RayDifferential& ray, const Scene& scene, IntegratorContext& ctx,
              Float* alpha) const override;
  bool startsFromFirstHit() const override { return true; }
  Spectrum LiFromFirstHit(const RayDifferential& ray, SurfaceInteraction* hit, Float tHit,
                          const Scene& scene, IntegratorContext& ctx, Float* alpha) const override;
  // The radiance arriving along ray without the emission of what it meets first (a surface's Le
  // or, when it escapes, the lights' Le): light that has scattered at least once, as an
  // irradiance estimate's rays need it (pbrt 2e §15.5.3). *hitDistance is the ray parameter of
  // the first hit, infinity when the ray escapes.
  Spectrum scatteredLi(const RayDifferential& ray, const Scene& scene, IntegratorContext& ctx,
                       Float* hitDistance) const;

 private:
  // The first hit when the caller found it: isect, null when the ray escapes, at distance t.
  struct FirstHit {
    SurfaceInteraction* isect;
    Float t;
  };
  Spectrum radiance(const RayDifferential& ray, const Scene& scene, IntegratorContext& ctx,
                    bool firstEmission, Float* alpha, Float* hitDistance,
                    const FirstHit* first = nullptr) const;
  int maxDepth_;
  int rrStartDepth_;
};

}  // namespace candela
