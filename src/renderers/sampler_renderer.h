// The sampler renderer (lrt draft §1.3, pbrt 2e §1.3.4): image tiles rendered in parallel under
// oneTBB, each with its own sampler clone, memory arena and counters. A pixel's value depends only
// on (scene, pixel, samples per pixel, seed), never on tiling or threads; with an integrator that
// splats (bdpt) also on the other pixels' samples, added order-independently (SplatBuffer).
#pragma once

#include <cstdint>
#include <optional>

#include "cameras/camera.h"
#include "film/film.h"
#include "integrators/integrator.h"
#include "integrators/volume_integrator.h"

namespace candela {

struct RenderOptions {
  int nThreads = 0;    // 0: all cores
  int tileSize = 16;   // pixels per tile side
  bool quiet = false;  // no progress output
  // The range of sample indices to take in each pixel: [firstSample, endSample), endSample < 0
  // meaning the sampler's samples per pixel. Rendering [0, a) then [a, b) into one film adds
  // every pixel's samples in the same order as rendering [0, b): the same bits.
  int firstSample = 0;
  int endSample = -1;
};

// A camera sample: its pixel and index there (what --cropwindow and --spp reproduce).
struct PixelSampleIndex {
  Point2i pixel;
  int index = 0;
  // Row by row, then by index: the order in which "first" is the same for any thread count.
  bool operator<(const PixelSampleIndex& o) const {
    if (pixel.y != o.pixel.y) return pixel.y < o.pixel.y;
    if (pixel.x != o.pixel.x) return pixel.x < o.pixel.x;
    return index < o.index;
  }
};

struct RenderResult {
  double seconds = 0;
  uint64_t samples = 0;
  RayStats rays;
  uint64_t nonFiniteSamples = 0;  // NaN or infinite radiance, dropped and counted
  // From the start of the last tile to the end of the render: the time in which some thread had
  // no tile left to take (the scheduling's tail).
  double tailSeconds = 0;
  // The first of them (in PixelSampleIndex order), when they came from camera samples.
  std::optional<PixelSampleIndex> firstNonFinite;
  // Adds another render's counts (rays, samples, non-finite samples, tails; the earlier first).
  void add(const RenderResult& other);
};

class SamplerRenderer {
 public:
  // The integrator is not const: render() first lets it prepare (SurfaceIntegrator::prepare).
  // volumeIntegrator: for scenes with a volume (Scene::volume()); each camera ray then gets
  // L = T·L_surface + L_volume (lrt draft §16.7). Null, or a scene without a volume: surface only.
  // Camera ray differentials are scaled by 1/sqrt(samples per pixel) (pbrt 3e §1.4.3), and by no
  // less than minDifferentialScale (pbrt-v3's renderer keeps 1/8).
  SamplerRenderer(const Camera& camera, const Sampler& sampler, SurfaceIntegrator& integrator,
                  const VolumeIntegrator* volumeIntegrator = nullptr,
                  Float minDifferentialScale = 0)
      : camera_(camera),
        sampler_(sampler),
        integrator_(integrator),
        volumeIntegrator_(volumeIntegrator),
        minDifferentialScale_(minDifferentialScale) {}
  RenderResult render(const Scene& scene, Film& film, const RenderOptions& options) const;

 private:
  const Camera& camera_;
  const Sampler& sampler_;
  SurfaceIntegrator& integrator_;
  const VolumeIntegrator* volumeIntegrator_;
  Float minDifferentialScale_;
};

}  // namespace candela
