// Light transport that renders the whole image at once instead of pixel by pixel: Metropolis
// light transport (pbrt 2e §15.7), stochastic progressive photon mapping (Hachisuka & Jensen
// 2009). A scene selects one by its integrator or Renderer statement, and it then replaces the
// sampler renderer and the surface integrator. Its image is still a pure function of (scene,
// sample count, seed): the same bits for any thread count, tile size and crop window, or, where
// that cannot hold, docs/scene-support.md says so.
#pragma once

#include <string>

#include "cameras/camera.h"
#include "film/film.h"
#include "renderers/progressive_render.h"
#include "scene/scene.h"

namespace candela {

class ImageRenderer {
 public:
  virtual ~ImageRenderer() = default;
  // Renders into film (whose crop window says which pixels to keep). options.render gives the
  // threads and quietness; a renderer that works in passes (SPPM's iterations) calls
  // options.afterPass after each, with PassReport::spp counting its passes' worth of samples, and
  // stops when it returns false or options.timeBudget would be passed; one that does not calls it
  // once at the end. result.spp is what the image's metadata records as samples per pixel.
  virtual ProgressiveResult render(const Scene& scene, const Camera& camera, Film& film,
                                   const ProgressiveOptions& options) const = 0;
  // Lines for --stats about what it built; empty when there is nothing to say.
  virtual std::string statsReport() const { return {}; }
};

}  // namespace candela
