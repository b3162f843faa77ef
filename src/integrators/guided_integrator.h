// The pixel-sample integrators that can guide their paths (path, volpath): with guiding (Müller,
// Gross & Novák 2017), the first passes of doubling sample counts, up to a quarter of the samples
// per pixel, train a GuidingField on the incident radiance their paths find; the integrator then
// draws some of its directions from the field's distribution, weighed by the mixture's density
// (one-sample MIS, §5.1). Every sample, training ones included, goes into the image: each is
// unbiased. Training passes take the full image and every sample index below the training's end
// whatever the crop window or sample range, so that the field, and with it every pixel, is the
// same bits as in the full render. With adaptive sampling (adaptive_render.h) every pixel takes
// the training passes, and pixels are judged from their end (or the minimum count) on.
#pragma once

#include <memory>
#include <string>

#include "integrators/pixel_sample_integrator.h"
#include "transport/guiding_field.h"

namespace candela {

// The samples per pixel that train path guiding's field: the largest power of two at most a
// quarter of samplesPerPixel (0 below 4, where nothing is guided).
int guidingTrainingSamples(int samplesPerPixel);

class GuidedIntegrator : public PixelSampleIntegrator {
 public:
  // Without guiding, PixelSampleIntegrator's; with it, training passes, then the rest.
  ProgressiveResult render(const RenderInputs& in, Film& film,
                           const ProgressiveOptions& options) override;
  // The field's passes and leaves, after a guided render.
  std::string statsReport() const override;

 protected:
  explicit GuidedIntegrator(bool guiding) : guiding_(guiding) {}
  // The field during a guided render (null otherwise), and whether paths record into it now.
  GuidingField* guide() const { return guide_.get(); }
  bool recording() const { return recording_; }
  // How a guided pass takes its samples: sampleLoop's by default.
  virtual SampleLoop guidedSampleLoop(const RenderInputs& in, const Film& film) const {
    return sampleLoop(in, film);
  }

 private:
  ProgressiveResult renderGuided(const RenderInputs& in, Film& film,
                                 const ProgressiveOptions& options);
  bool guiding_;
  std::unique_ptr<GuidingField> guide_;
  bool recording_ = false;
};

}  // namespace candela
