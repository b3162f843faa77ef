// Direct lighting estimators shared by the integrators (pbrt 2e §15.1): one light sample and one
// BSDF sample combined by multiple importance sampling with the power heuristic.
#pragma once

#include "reflection/bsdf.h"
#include "transport/directional_quadtree.h"
#include "transport/guiding_field.h"
#include "transport/integrator_context.h"

namespace candela {

// Müller et al. 2017's fixed share of BSDF sampling in the guided mixture (§5.1).
inline constexpr Float kGuidedBsdfShare = 0.5f;

// How a path chose its next direction when not by the BSDF alone (path guiding): with
// probability bsdfShare by the BSDF, else by guide. The light strategy's MIS weight then takes
// the mixture's density, the one the path's emission hits are weighed with.
struct ScatteringMixture {
  const DirectionalQuadtree* guide = nullptr;
  Float bsdfShare = 1;
  Float pdf(const BSDF& bsdf, const Vector3f& wo, const Vector3f& wi, int flags) const {
    Float p = bsdf.pdf(wo, wi, flags);
    return guide ? bsdfShare * p + (1 - bsdfShare) * guide->pdf(wi) : p;
  }
  // One sample of the mixture (guide set): by the BSDF when uMix < bsdfShare, with uComponent
  // and u, else by the guide with u. Returns the BSDF's value for *wi, *pdf the mixture's density
  // (0 and black when the BSDF drew nothing); *type is non-specular.
  Spectrum sample(const BSDF& bsdf, const Vector3f& wo, Float uComponent, const Point2f& u,
                  Float uMix, Vector3f* wi, Float* pdf, BxDFType* type) const;
};

// The mixture at p for a guided path (field non-null): the field's distribution there once
// trained, at a vertex whose BSDF has lobes and none of them specular (a delta has no density
// to mix); else none (guide null: sample the BSDF alone).
ScatteringMixture guidedMixture(const GuidingField* field, const BSDF& bsdf, const Point3f& p);

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
// (mixture: how the path's next direction was chosen; null: by the BSDF.)
Spectrum sampleOneLightAgainstBSDF(const SurfaceInteraction& it, const BSDF& bsdf,
                                   const Scene& scene, IntegratorContext& ctx, Float uChoice,
                                   const Point2f& uLight,
                                   const ScatteringMixture* mixture = nullptr);
// The same for a light the caller chose (a LightSampler) with probability choicePdf.
Spectrum sampleLightAgainstBSDF(const SurfaceInteraction& it, const BSDF& bsdf, const Light& light,
                                Float choicePdf, const Scene& scene, IntegratorContext& ctx,
                                const Point2f& uLight, const ScatteringMixture* mixture = nullptr);

}  // namespace candela
