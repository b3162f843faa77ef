// Parameters of Integrator "mlt" (pbrt-v3) and Renderer "metropolis" (pbrt-v2), with their
// defaults. Bad values are SceneErrors at the parameter.
//
// "mlt" (pbrt 3e §16.4, over bdpt's paths, one MIS-weighted strategy per path):
//   maxdepth 5               most scattering events of a path
//   bootstrapsamples 100000  independent paths (per depth) that estimate b and pick the starts
//   chains 1000              Markov chains, run in parallel
//   mutationsperpixel 100    proposals per pixel of the full image, over all chains (--spp
//                            replaces it)
//   largestepprobability 0.3 probability that a proposal is a fresh path
//   sigma 0.01               standard deviation of a small step in primary sample space
// "metropolis" (pbrt 2e §15.7, on the same chains, with pbrt-v2's exponentially distributed
// small steps of 1/1024 to 1/64 (Kelemen et al.) in place of Gaussian ones):
//   maxdepth 7, bootstrapsamples 100000, largestepprobability 0.25 as above
//   samplesperpixel 100      proposals per pixel (--spp replaces it)
//   bidirectional true       paths of bdpt's strategies; false: unidirectional paths (light
//                            samples at every vertex, emitters hit after specular bounces)
//   dodirectseparately true  direct lighting by the directlighting integrator, left out of the
//                            chains
//   directsamples 4          that integrator's samples per pixel
//   maxconsecutiverejects 512  after so many rejections in a row a proposal is accepted
//   chains 1000              (candela's, not pbrt-v2's) Markov chains; each starts from one
//                            bootstrap path, so chains of few mutations (small images) keep some
//                            start-up bias: fewer chains, longer each, for those
// --quick divides the sample counts (mutations, bootstrap, direct samples) by 4 (pbrt-v2's rule).
#include "integrators/integrator_plugins.h"
#include "integrators/metropolis/metropolis_integrator.h"

namespace candela {

namespace {

int atLeast(const IntegratorInputs& desc, const char* name, int def, int minimum) {
  return desc.params.getOneInt(name, def, ValueRange::atLeast(minimum), desc.loc);
}

Float probability(const IntegratorInputs& desc, const char* name, Float def) {
  return desc.params.getOneFloat(name, def, ValueRange::within(0, 1), desc.loc);
}

const CameraImportance& importanceOf(const IntegratorInputs& desc) {
  const CameraImportance* importance = desc.camera ? desc.camera->importance() : nullptr;
  if (!importance)
    throw SceneError(desc.loc, std::string("'")
                                   .append(desc.name)
                                   .append("' connects light paths to the camera, which the '")
                                   .append(desc.camera ? desc.camera->kind() : "(none)")
                                   .append("' camera does not support (use 'perspective')"));
  return *importance;
}

int quarterIfQuick(int n, const IntegratorInputs& c) { return c.quick ? std::max(1, n / 4) : n; }

}  // namespace

std::unique_ptr<Integrator> createMltRenderer(const IntegratorInputs& desc) {
  MetropolisSettings s;
  s.maxDepth = atLeast(desc, "maxdepth", 5, 0);
  s.bootstrapSamples = quarterIfQuick(atLeast(desc, "bootstrapsamples", 100000, 1), desc);
  s.chains = atLeast(desc, "chains", 1000, 1);
  s.mutationsPerPixel = atLeast(desc, "mutationsperpixel", 100, 1);
  if (desc.sppOverride > 0) s.mutationsPerPixel = desc.sppOverride;
  s.mutationsPerPixel = quarterIfQuick(int(s.mutationsPerPixel), desc);
  s.largeStepProbability = probability(desc, "largestepprobability", 0.3f);
  s.sigma = desc.params.getOneFloat("sigma", 0.01f, ValueRange::positive(), desc.loc);
  s.bidirectional = true;
  return std::make_unique<MetropolisIntegrator>(importanceOf(desc), s, desc.seed);
}

std::unique_ptr<Integrator> createMetropolisIntegrator(const IntegratorInputs& desc) {
  MetropolisSettings s;
  s.maxDepth = atLeast(desc, "maxdepth", 7, 0);
  s.bootstrapSamples = quarterIfQuick(atLeast(desc, "bootstrapsamples", 100000, 1), desc);
  s.mutationsPerPixel = atLeast(desc, "samplesperpixel", 100, 1);
  if (desc.sppOverride > 0) s.mutationsPerPixel = desc.sppOverride;
  s.mutationsPerPixel = quarterIfQuick(int(s.mutationsPerPixel), desc);
  s.largeStepProbability = probability(desc, "largestepprobability", 0.25f);
  s.maxConsecutiveRejects = atLeast(desc, "maxconsecutiverejects", 512, 1);
  s.chains = atLeast(desc, "chains", 1000, 1);
  s.smallStep = PrimarySamples::SmallStep::Exponential;
  s.bidirectional = desc.params.getOneBool("bidirectional", true);
  bool direct = desc.params.getOneBool("dodirectseparately", true);
  int directSamples = quarterIfQuick(atLeast(desc, "directsamples", 4, 1), desc);
  s.excludeDirect = direct;
  return std::make_unique<MetropolisIntegrator>(importanceOf(desc), s, desc.seed,
                                                direct ? directSamples : 0);
}

}  // namespace candela
