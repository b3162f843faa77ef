// The one interface every integrator implements (as pbrt-v4's Integrator::Render): given the
// scene, the camera and the scene's sampler, it renders the film. PixelSampleIntegrator
// (pixel_sample_integrator.h) supplies the tiled, deterministic loop over camera samples and asks
// its subclasses only for radiance (lrt draft ch. 16; pbrt 2e ch. 15); SPPM and Metropolis
// render the whole image their own way. Either way the image is a pure function of (scene,
// sample count, seed): the same bits for any thread count, tile size and crop window, or, where
// that cannot hold, docs/scene-support.md says so.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/image_buffer.h"
#include "integrators/render_options.h"
#include "scene/scene.h"
#include "transport/integrator_context.h"

namespace candela {

class Camera;
class Film;
class Sampler;
class VolumeIntegrator;

// An image an integrator makes besides the film's (bdpt's per-strategy images), written next to
// the output under its name.
struct NamedImage {
  std::string name;
  ImageBuffer image;
};

// What preprocess may use from the build besides the scene.
struct PreprocessOptions {
  uint64_t seed = 0;  // the render's seed: a prepass's random numbers derive from it
  int nThreads = 0;   // 0: all cores
  bool showProgress = false;
  bool quick = false;                            // --quick: a cheaper, rougher prepass
  bool sceneHasSpecular = true;                  // some material may scatter perfectly specularly
  bool sceneHasSubsurface = true;                // some material has a subsurface() medium
  Float shutterOpen = 0, shutterClose = 0;       // the camera's: the times a prepass samples
  std::function<void(const std::string&)> warn;  // may be empty
};

// What a pixel's value is made of. It decides what the command may do with a render: split it by
// sample range (--sample-range) only when each pixel's samples are its own, and estimate its
// error from the pixels' own variance (--target-error without --reference) likewise.
enum class PixelLight {
  OwnSamples,  // the weighted mean of the pixel's own camera samples
  Splatted,    // those, plus light other pixels' samples add to it (light tracing)
  WholeImage,  // made for the whole image at once (Markov chains, photon gathering)
};

// What render() is given besides the film.
struct RenderInputs {
  const Scene& scene;
  const Camera& camera;
  // The scene's sampler: its samples per pixel and seed. An integrator that samples its own way
  // (SPPM's iterations, Metropolis' chains) reads what it needs of it or nothing.
  const Sampler& sampler;
  // The integrator of pbrt-v2 Volume regions, for a scene that has them; null otherwise.
  const VolumeIntegrator* volumeIntegrator = nullptr;
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  // Work done once at scene build, before the camera and film matter (photon maps, virtual
  // point lights); deterministic for any thread count.
  virtual void preprocess(const Scene&, const PreprocessOptions&) {}
  // Renders into film (whose crop window says which pixels to keep). options.render gives the
  // threads, tile size, quietness and sample range. An integrator that renders in passes calls
  // options.afterPass after each, with PassReport::spp counting its passes' worth of samples, and
  // stops when it returns false or options.timeBudget would be passed; one that renders in one
  // go calls it once at the end. result.spp is what the image's metadata records as samples per
  // pixel. Not const: an integrator may build what needs the camera and film on its first render.
  virtual ProgressiveResult render(const RenderInputs& in, Film& film,
                                   const ProgressiveOptions& options) = 0;
  // Lines for --stats about what it built; empty when there is nothing to say.
  virtual std::string statsReport() const { return {}; }
  virtual PixelLight pixelLight() const { return PixelLight::OwnSamples; }
  // Images to write besides the film's once rendering is done (film: the render's, for its pixel
  // bounds and scale).
  virtual std::vector<NamedImage> extraImages(const Film& /*film*/) const { return {}; }
};

}  // namespace candela
