// The first step of every light-tracing method (photon mapping, pbrt 2e §15.6; virtual point
// lights, §15.4; SPPM): a light chosen in proportion to its power, and a particle leaving it.
#pragma once

#include <optional>

#include "core/sampling.h"
#include "scene/scene.h"

namespace candela {

// The lights' luminous power as a distribution over their indices; none when no light emits.
std::optional<Distribution1D> lightPowerDistribution(const Scene& scene);

struct LightPathStart {
  Ray ray;
  Spectrum beta;  // the particle's weight: Le |cos| / (pmf pdfPos pdfDir), pbrt 2e eq. 15.16
};

// uLight picks the light, uPos and uDir its sampleLe. Nothing when the sample carries no finite,
// non-zero power.
std::optional<LightPathStart> startLightPath(const Scene& scene, const Distribution1D& lightChoice,
                                             Float uLight, const Point2f& uPos, const Point2f& uDir,
                                             Float time);

}  // namespace candela
