// Direct lighting estimators shared by the integrators (pbrt 2e §15.1): one light sample and one
// BSDF sample combined by multiple importance sampling with the power heuristic.
#pragma once

#include "reflection/bsdf.h"
#include "transport/integrator_context.h"

namespace candela {

// Radiance reflected at it toward it.wo from light `light`, one sample of each strategy. The two
// functions below that take the context also attenuate by the scene's volume, if it has one.
Spectrum estimateDirect(const SurfaceInteraction& it, const BSDF& bsdf, const Light& light,
                        const Point2f& uLight, const Point2f& uScattering, Float uComponent,
                        const Scene& scene, RayStats& stats);

// Every light, each with its nSamples samples.
Spectrum uniformSampleAllLights(const SurfaceInteraction& it, const BSDF& bsdf, const Scene& scene,
                                IntegratorContext& ctx);

// One light chosen uniformly, its estimate divided by the choice probability.
Spectrum uniformSampleOneLight(const SurfaceInteraction& it, const BSDF& bsdf, const Scene& scene,
                               IntegratorContext& ctx);

// One light chosen uniformly and one sample of it, weighted by the power heuristic against the
// BSDF's sampling of all its components: the light strategy of a path whose next direction is
// the BSDF's sample, which carries the BSDF strategy (pbrt 4e §13.4; PathIntegrator). Attenuates
// by the scene's volume.
Spectrum sampleOneLightAgainstBSDF(const SurfaceInteraction& it, const BSDF& bsdf,
                                   const Scene& scene, IntegratorContext& ctx);
// The same with the light's choice and sample values given (drawn by the caller, in the order
// the other draws them: the choice, then the sample).
Spectrum sampleOneLightAgainstBSDF(const SurfaceInteraction& it, const BSDF& bsdf,
                                   const Scene& scene, IntegratorContext& ctx, Float uChoice,
                                   const Point2f& uLight);
// The same for a light the caller chose (a LightSampler) with probability choicePdf.
Spectrum sampleLightAgainstBSDF(const SurfaceInteraction& it, const BSDF& bsdf, const Light& light,
                                Float choicePdf, const Scene& scene, IntegratorContext& ctx,
                                const Point2f& uLight);

}  // namespace candela
