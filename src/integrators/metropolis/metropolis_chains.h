// Primary-sample-space Metropolis light transport (Kelemen et al. 2002; pbrt 2e §15.7, pbrt 3e
// §16.4) over fixed-length bidirectional paths: a bootstrap of independent paths estimates the
// image's total luminance b and gives the chains start states in proportion to their
// contribution; then every chain proposes mutations (large steps: all numbers fresh; small
// steps: Gaussian perturbations) accepted with probability min(1, y'/y), y the luminance, and
// splats both the current and the proposed path weighted by their acceptance (the
// expected-values trick), each scaled by b / y. Chain c's numbers depend only on (seed, c) and
// its start state; the splats are order-independent fixed-point sums, so the image is the same
// bits for any thread count, and a crop window keeps its region of the full render.
#pragma once

#include <cstdint>

#include "cameras/camera.h"
#include "film/film.h"
#include "integrators/bdpt.h"
#include "integrators/metropolis/primary_samples.h"
#include "integrators/pixel_sample_integrator.h"

namespace candela {

struct MetropolisSettings {
  int maxDepth = 5;
  int64_t bootstrapSamples = 100000;
  int chains = 1000;
  int64_t mutationsPerPixel = 100;
  Float largeStepProbability = 0.3f;
  Float sigma = 0.01f;  // of Gaussian small steps
  // pbrt-v3's Gaussian small steps of sigma, or pbrt-v2's exponential ones (PrimarySamples).
  PrimarySamples::SmallStep smallStep = PrimarySamples::SmallStep::Gaussian;
  // Bidirectional: one strategy of a path picked uniformly and weighted by MIS (pbrt-v3);
  // otherwise unidirectional paths (BdptIntegrator::Weighting::Unidirectional).
  bool bidirectional = true;
  // After this many rejections in a row the next proposal is accepted (pbrt-v2's small bias
  // against stuck chains); 0: never.
  int64_t maxConsecutiveRejects = 0;
  // Leave out the paths that direct lighting renders separately (see
  // BdptIntegrator::fixedLengthContribution's excludeDirect).
  bool excludeDirect = false;
};

struct MetropolisStats {
  double b = 0;  // the bootstrap's estimate of the image's total luminance per pixel
  uint64_t proposals = 0, accepted = 0, forcedAccepts = 0;
};

// Adds the chains' splats to film (scaled so that the film shows the image) and returns the
// rays traced; the paths come from `paths`, prepared for scene.
RenderResult runMetropolisChains(const MetropolisSettings& settings, const BdptIntegrator& paths,
                                 const Scene& scene, const Camera& camera, Film& film,
                                 uint64_t seed, const RenderOptions& options,
                                 MetropolisStats* stats);

}  // namespace candela
