#include "renderers/metropolis/metropolis_renderer.h"

#include <sstream>

#include "integrators/direct_lighting.h"
#include "renderers/sampler_renderer.h"

namespace candela {

ProgressiveResult MetropolisRenderer::render(const Scene& scene, const Camera& camera, Film& film,
                                             const ProgressiveOptions& options) const {
  // The chains' paths: bdpt's subpaths and connections, its light choice by power.
  BdptIntegrator paths(importance_, settings_.maxDepth, BdptIntegrator::LightChoice::Power);
  paths.preprocess(scene, PreprocessOptions{});
  ProgressiveResult result;
  if (directSamples_ > 0) {
    // pbrt 2e §15.7: the direct lighting, which the chains leave out, by the sampler renderer
    // with a random sampler of directSamples per pixel; its maxdepth bounds the specular
    // bounces before the surface that is lit as the chains' maxdepth bounds the path.
    DirectLightingIntegrator direct(DirectLightingIntegrator::Strategy::All, settings_.maxDepth);
    std::unique_ptr<Sampler> sampler =
        createSampler("random", ParamSet(), seed_, directSamples_, FileLoc{});
    SamplerRenderer renderer(camera, *sampler, direct);
    result.total = renderer.render(scene, film, options.render);
  }
  MetropolisStats stats;
  RenderResult chains =
      runMetropolisChains(settings_, paths, scene, camera, film, seed_, options.render, &stats);
  result.total.seconds += chains.seconds;
  result.total.samples += chains.samples;
  result.total.rays += chains.rays;
  result.total.nonFiniteSamples += chains.nonFiniteSamples;
  result.spp = int(std::min<int64_t>(settings_.mutationsPerPixel, INT32_MAX));
  result.passes = 1;
  std::ostringstream os;
  os << "Metropolis\n  b (mean luminance over the image)  " << stats.b << "\n  proposals  "
     << stats.proposals << "\n  accepted  " << stats.accepted;
  if (stats.proposals)
    os << " (" << 100.0 * double(stats.accepted) / double(stats.proposals) << "%)";
  os << "\n";
  if (settings_.maxConsecutiveRejects > 0)
    os << "  forced accepts  " << stats.forcedAccepts << "\n";
  report_ = os.str();
  if (options.afterPass) {
    PassReport pass;
    pass.pass = 0;
    pass.spp = result.spp;
    pass.seconds = result.total.seconds;
    pass.total = result.total;
    options.afterPass(pass);
  }
  return result;
}

}  // namespace candela
