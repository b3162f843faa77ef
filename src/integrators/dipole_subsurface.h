// "dipolesubsurface" (pbrt 2e §16.5; Jensen et al. 2001, Jensen and Buhler 2002): "directlighting"
// (all lights) with the specular recursion, plus, on surfaces with a subsurface material, the
// light that entered elsewhere and diffused back out:
//   Lo += Ft(eta, wo) / pi * (1 - Fdr(eta)) * sum_i Rd(|p - p_i|) E_i A_i,
// over sample points p_i with irradiance E_i and area A_i placed at preprocess time on every
// translucent surface (subsurface_points.h), summed hierarchically (subsurface_octree.h). E_i is
// the irradiance before the boundary; 1 - Fdr is the diffuse transmittance that lets it in, as in
// pbrt-v2. E_i is direct light only (no indirect bounce into the samples).
// Parameters (pbrt-v2's): maxdepth 5, maxerror .05, minsampledistance .25, and pointsfile: sample
// points given instead of placed (pbrt-v2's format, see assembly/integrator_factory.cpp).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "integrators/specular_recursion.h"
#include "transport/subsurface_octree.h"
#include "transport/subsurface_points.h"

namespace candela {

struct DipoleSubsurfaceSettings {
  int maxDepth = 5;
  Float maxError = 0.05f;
  Float minSampleDistance = 0.25f;
  // Points read from pointsfile (irradiance zero): used instead of placing points when not empty.
  std::vector<SubsurfacePoint> givenPoints;
  std::string pointsFile;  // where they came from, for --stats
};

class DipoleSubsurfaceIntegrator : public SpecularRecursionIntegrator {
 public:
  explicit DipoleSubsurfaceIntegrator(const DipoleSubsurfaceSettings& s)
      : SpecularRecursionIntegrator(s.maxDepth), settings_(s) {}
  void preprocess(const Scene& scene, const PreprocessOptions& options) override;
  std::string statsReport() const override;
  const SubsurfaceOctree& octree() const { return octree_; }

 protected:
  Spectrum directLight(const SurfaceInteraction& isect, const BSDF& bsdf, const Scene& scene,
                       IntegratorContext& ctx) const override;

 private:
  DipoleSubsurfaceSettings settings_;
  SubsurfaceOctree octree_;
  Float surfaceArea_ = 0;
  uint64_t linesTraced_ = 0, candidates_ = 0, prepassRays_ = 0;
};

}  // namespace candela
