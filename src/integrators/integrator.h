// Surface integrators (lrt draft ch. 16; pbrt 2e ch. 15): the radiance arriving along a camera
// ray. An integrator is shared by all threads and so is const; per-thread state travels in
// the sampler, the arena and the counters.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/image_buffer.h"
#include "core/memory.h"
#include "samplers/halton_sampler.h"
#include "samplers/sampler.h"
#include "scene/scene.h"

namespace candela {

class Camera;
class Film;

// How the renderer runs a prepass: threads (0: all cores), whether to show progress, and what
// every thread that traces rays must call first (the renderer's floating-point mode; empty: none).
struct PrepassOptions {
  int nThreads = 0;
  bool quiet = true;
  std::function<void()> setUpThread;
};

class SplatBuffer;
class VolumeIntegrator;

// An image an integrator makes besides the film's (bdpt's per-strategy images), written next to
// the output under its name.
struct NamedImage {
  std::string name;
  ImageBuffer image;
};

struct IntegratorContext {
  Sampler& sampler;
  MemoryArena& arena;
  RayStats& stats;
  // Where an integrator that splats() adds light landing on other pixels; null otherwise.
  SplatBuffer* splats = nullptr;
  // The volume integrator whose transmittance shadow rays and path segments take when the scene
  // has a volume (see volume_transmittance.h); null otherwise.
  const VolumeIntegrator* volumeIntegrator = nullptr;
  // The sampler when it is the Halton sampler (a final class), else null: through get1D and get2D
  // below its values are then computed inline, not through a virtual call, which was a large
  // part of the few nanoseconds a value takes.
  HaltonSampler* halton = dynamic_cast<HaltonSampler*>(&sampler);

  // The sampler's next values: sampler.get1D() and sampler.get2D().
  Float get1D() { return halton ? halton->get1D() : sampler.get1D(); }
  Point2f get2D() { return halton ? halton->get2D() : sampler.get2D(); }
  void skip1D() { halton ? halton->skip1D() : sampler.skip1D(); }  // see Sampler::skip1D
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

class SurfaceIntegrator {
 public:
  virtual ~SurfaceIntegrator() = default;
  // Work done once at scene build, before the camera and film matter (photon maps, virtual
  // point lights); deterministic for any thread count.
  virtual void preprocess(const Scene&, const PreprocessOptions&) {}
  // Work that needs the camera and the film: the renderer calls it before the first pixel of
  // every render, and an integrator that has already done its work returns at once. What it
  // builds must be a function of (scene, camera, film resolution, sampler seed) only, never of
  // threads, crop window or order of completion. Returns the rays it traced.
  virtual RayStats prepare(const Scene&, const Camera&, const Sampler&, const Film&,
                           const PrepassOptions&) {
    return {};
  }
  // Lines for --stats about what prepare built; empty when there is nothing to say.
  virtual std::string statsReport() const { return {}; }
  // Whether Li also adds light to other pixels through ctx.splats (light tracing). The renderer
  // then takes every pixel's samples, those outside the crop window too (see SamplerRenderer).
  virtual bool splats() const { return false; }
  // Whether Li carries light through the scene's media itself (volpath). The renderer then runs
  // no volume integrator on top of it, which would count the volume's light twice.
  virtual bool rendersMedia() const { return false; }
  // Whether every ray Li traces between two points is attenuated by pbrt-v2 Volume regions
  // (through volumeTransmittance), not only its camera ray (the renderer's) and its direct
  // lighting; the scene build warns for integrators that do not (photons, gather rays, light
  // subpaths would cross the volume unattenuated).
  virtual bool attenuatesEveryRay() const { return rendersMedia(); }
  // Whether Li reads the camera ray's differentials even where no texture does (the irradiance
  // cache spaces its samples by the pixel footprint).
  virtual bool needsRayDifferentials() const { return false; }
  // Images to write besides the film's once rendering is done (film: the render's, for its pixel
  // bounds and scale).
  virtual std::vector<NamedImage> extraImages(const Film& /*film*/) const { return {}; }
  // *alpha is set to 1 when the ray hits a surface and 0 when it escapes.
  virtual Spectrum Li(const RayDifferential& ray, const Scene& scene, IntegratorContext& ctx,
                      Float* alpha) const = 0;
  // Whether Li can start from the camera ray's closest hit found by the renderer (LiFromFirstHit
  // below); the renderer then traces a pixel's camera rays together, as coherent rays.
  virtual bool startsFromFirstHit() const { return false; }
  // Li for a camera ray whose closest hit is known: hit, at distance tHit, or null when the ray
  // escapes; ray as the camera made it (tMax not shortened). *hit may be changed. By default the
  // hit is found again.
  virtual Spectrum LiFromFirstHit(const RayDifferential& ray, SurfaceInteraction* /*hit*/,
                                  Float /*tHit*/, const Scene& scene, IntegratorContext& ctx,
                                  Float* alpha) const {
    return Li(ray, scene, ctx, alpha);
  }
};

}  // namespace candela
