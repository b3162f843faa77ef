// The Metropolis integrators, which render the whole image: pbrt-v3's Integrator "mlt" (pbrt 3e
// §16.4) and pbrt-v2's Renderer "metropolis" (pbrt 2e §15.7), both on the chains of
// metropolis_chains.h; the latter may render direct lighting separately with the directlighting
// integrator.
#pragma once

#include <string>

#include "integrators/integrator.h"
#include "integrators/metropolis/metropolis_chains.h"

namespace candela {

class MetropolisIntegrator : public Integrator {
 public:
  // directSamples > 0: direct lighting by the directlighting integrator at that many samples
  // per pixel (and left out of the chains: settings.excludeDirect must be set).
  MetropolisIntegrator(const CameraImportance& importance, const MetropolisSettings& settings,
                       uint64_t seed, int directSamples = 0)
      : importance_(importance), settings_(settings), seed_(seed), directSamples_(directSamples) {}
  ProgressiveResult render(const RenderInputs& in, Film& film,
                           const ProgressiveOptions& options) override;
  PixelLight pixelLight() const override { return PixelLight::WholeImage; }
  std::string statsReport() const override { return report_; }

 private:
  const CameraImportance& importance_;
  MetropolisSettings settings_;
  uint64_t seed_;
  int directSamples_;
  mutable std::string report_;
};

}  // namespace candela
