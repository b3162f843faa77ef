// Stochastic progressive photon mapping (Hachisuka & Jensen 2009; pbrt 3e §16.2), pbrt-v3's
// Integrator "sppm". Each iteration traces one camera path per pixel to its first non-specular
// surface (the visible point, with direct light by light sampling), shoots a fresh set of photons
// and gathers those that land within each visible point's radius; the radius then shrinks so that
// bias and variance both vanish as iterations grow (a consistent estimator).
//
// Determinism: camera path k of a pixel and photon i of iteration k draw their numbers from
// (seed, pixel or photon index, k) alone; photons run in fixed blocks and their deposits are summed
// in photon order, so the image is the same bits for any thread count; visible points exist only
// in the film's pixel bounds but every photon is shot whatever the crop, so a crop window renders
// its pixels exactly as the full image does.
#pragma once

#include <cstdint>
#include <mutex>
#include <string>

#include "integrators/integrator.h"

namespace candela {

struct SppmSettings {
  int iterations = 64;               // pbrt-v3 "numiterations"
  int maxDepth = 5;                  // camera and photon path vertices, as pbrt-v3
  int64_t photonsPerIteration = -1;  // -1: the full image's pixel count
  Float initialRadius = 1;           // pbrt-v3 "radius", in scene units
  uint64_t seed = 0;
};

struct SppmStats {
  int iterations = 0;
  uint64_t photonsShot = 0;
  uint64_t visiblePoints = 0;  // summed over the iterations
  size_t maxGridBytes = 0;
};

class SppmIntegrator : public Integrator {
 public:
  explicit SppmIntegrator(const SppmSettings& settings) : settings_(settings) {}
  ProgressiveResult render(const RenderInputs& in, Film& film,
                           const ProgressiveOptions& options) override;
  PixelLight pixelLight() const override { return PixelLight::WholeImage; }
  std::string statsReport() const override;
  const SppmSettings& settings() const { return settings_; }

 private:
  SppmSettings settings_;
  // What the last render did, for --stats (render is const, as every renderer's).
  mutable std::mutex statsMutex_;
  mutable SppmStats stats_;
};

}  // namespace candela
