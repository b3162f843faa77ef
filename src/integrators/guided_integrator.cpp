#include "integrators/guided_integrator.h"

#include <algorithm>

#include "integrators/adaptive_render.h"
#include "integrators/progressive_render.h"

namespace candela {

int guidingTrainingSamples(int samplesPerPixel) {
  int t = 0;
  while (samplesPerPixel >= 4 * std::max(1, 2 * t)) t = std::max(1, 2 * t);
  return t;
}

ProgressiveResult GuidedIntegrator::render(const RenderInputs& in, Film& film,
                                           const ProgressiveOptions& options) {
  if (!guiding_) return PixelSampleIntegrator::render(in, film, options);
  return renderGuided(in, film, options);
}

ProgressiveResult GuidedIntegrator::renderGuided(const RenderInputs& in, Film& film,
                                                 const ProgressiveOptions& options) {
  const int spp = in.sampler.samplesPerPixel();
  const int trained = guidingTrainingSamples(spp);
  // The samples the film takes: options.render's range.
  const int first = std::max(0, options.render.firstSample);
  const int end = options.render.endSample < 0 ? spp : std::min(options.render.endSample, spp);
  guide_ = std::make_unique<GuidingField>(in.scene.worldBound());
  int finished = 0;
  auto renderPass = [&](const RenderOptions& pass) {
    SampleLoop loop = guidedSampleLoop(in, film);
    if (pass.endSample <= trained) {
      // Training: the full image, every sample; the film keeps those of its range and crop.
      loop.pixels = Bounds2i(Point2i(0, 0), film.fullResolution());
      loop.filmFirstSample = first;
      loop.filmEndSample = end;
      // Every pixel: adaptive sampling judges none before the training ends.
      RenderOptions every = pass;
      every.pixels = nullptr;
      recording_ = true;
      RenderResult r;
      try {
        r = renderPixelSamples(in, film, every, loop);
      } catch (...) {
        recording_ = false;
        throw;
      }
      recording_ = false;
      guide_->finishPass(finished++);
      return r;
    }
    RenderOptions own = pass;
    own.firstSample = std::max(pass.firstSample, first);
    own.endSample = std::min(pass.endSample, end);
    if (own.firstSample >= own.endSample) return RenderResult();
    return renderPixelSamples(in, film, own, loop);
  };
  if (options.adaptive.enabled()) {
    // The training passes, then adaptive ones from their end (or the minimum count) on.
    std::vector<int> training = trained > 0 ? doublingPassEnds(trained) : std::vector<int>{};
    return renderAdaptive(renderPass, film, spp, options, training);
  }
  std::vector<int> ends = doublingPassEnds(spp);
  if (options.afterPass || options.timeBudget > 0) return renderPasses(renderPass, ends, options);
  // One pass after the training ones.
  while (!ends.empty() && ends.back() > trained) ends.pop_back();
  ends.push_back(spp);
  ProgressiveResult result;
  for (size_t i = 0; i < ends.size(); ++i) {
    RenderOptions pass = options.render;
    pass.firstSample = i == 0 ? 0 : ends[i - 1];
    pass.endSample = ends[i];
    if (i + 1 < ends.size()) pass.quiet = true;
    result.total.add(renderPass(pass));
  }
  result.spp = spp;
  result.passes = 1;
  return result;
}

std::string GuidedIntegrator::statsReport() const {
  if (!guide_) return {};
  return "Path guiding: " + std::to_string(guide_->passesFinished()) + " training passes, " +
         std::to_string(guide_->leaves()) + " spatial leaves\n";
}

}  // namespace candela
