// "igi": instant global illumination (Keller 1997; pbrt 2e §15.4). Emission and direct light as
// "directlighting" computes them with all lights, plus the light of one set of virtual point
// lights (chosen per pixel sample), each gathered with its geometric term bounded by glimit and
// a shadow ray; the energy the bound removes is added back by BSDF-sampled gather rays (Kollig
// and Keller 2004), and perfect specular surfaces are followed by recursion to maxdepth.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "integrators/pixel_sample_integrator.h"
#include "reflection/bsdf.h"
#include "transport/virtual_point_lights.h"

namespace candela {

struct IgiParameters {
  int pathsPerSet = 64;       // "nlights"
  int nSets = 4;              // "nsets"
  Float rrThreshold = 1e-4f;  // "rrthreshold": VPL contributions below it face roulette
  int maxDepth = 5;           // "maxdepth": levels of specular recursion and gathering
  Float gLimit = 10;          // "glimit": bound on the geometric term
  int gatherSamples = 16;     // "gathersamples": compensation rays at the camera vertex
};

class InstantGlobalIlluminationIntegrator : public PixelSampleIntegrator {
 public:
  explicit InstantGlobalIlluminationIntegrator(const IgiParameters& params) : params_(params) {}
  void preprocess(const Scene& scene, const PreprocessOptions&) override;
  Spectrum Li(const RayDifferential& ray, const Scene& scene, IntegratorContext& ctx,
              Float* alpha) const override;
  std::string statsReport() const override;
  const VirtualPointLightSets& virtualLights() const { return vpls_; }

 private:
  // Radiance along ray. withEmission is false on gather rays, which look for the light that
  // surfaces reflect: their emission is direct light, counted at the gathering point already.
  Spectrum trace(const RayDifferential& ray, const Scene& scene, IntegratorContext& ctx, int set,
                 int depth, bool withEmission, Float* alpha) const;
  // Light reflected at isect, a surface with a material, toward isect.wo: direct, from the VPLs,
  // the compensation of their bound, and through specular recursion.
  Spectrum scatter(SurfaceInteraction& isect, const RayDifferential& ray, const Scene& scene,
                   IntegratorContext& ctx, int set, int depth) const;
  Spectrum gatherVirtualLights(const SurfaceInteraction& isect, const BSDF& bsdf,
                               const Scene& scene, IntegratorContext& ctx, int set) const;
  Spectrum compensateBound(const SurfaceInteraction& isect, const BSDF& bsdf, const Scene& scene,
                           IntegratorContext& ctx, int set, int depth) const;

  IgiParameters params_;
  VirtualPointLightSets vpls_;
};

}  // namespace candela
