// The pixel-sample integrators (lrt draft §1.3, pbrt 2e §1.3.4, pbrt-v4's RayIntegrator): image
// tiles rendered in parallel under oneTBB, each thread with its own sampler clone, memory arena
// and counters, every camera sample's radiance asked of the subclass (Li). A pixel's value
// depends only on (scene, pixel, samples per pixel, seed), never on tiling or threads; with an
// integrator that splats (bdpt) also on the other pixels' samples, added order-independently
// (SplatBuffer).
#pragma once

#include <cstdint>

#include "cameras/camera.h"
#include "film/film.h"
#include "integrators/integrator.h"
#include "transport/volume_integrator.h"

namespace candela {

// How pbrt-v2 Volume regions reach an integrator's light.
enum class VolumeRegionLight {
  // The loop attenuates the camera ray and adds the volume's light (L = T·L_surface + L_volume,
  // lrt draft §16.7); the integrator attenuates its direct lighting, no other ray.
  CameraRayAndDirect,
  // As CameraRayAndDirect, and every other ray the integrator traces between two points.
  EveryRay,
  // The integrator carries light through the regions itself (volpath): the loop adds nothing,
  // which would count the volume's light twice.
  Integrator,
};

// An integrator whose radiance can start from the camera ray's closest hit: the loop then traces
// each group of a pixel's camera rays together, as coherent rays (Embree's packets).
class FirstHitRadiance {
 public:
  // Li for a camera ray whose closest hit is known: hit, at distance tHit, or null when the ray
  // escapes; ray as the camera made it (tMax not shortened). *hit may be changed.
  virtual Spectrum LiFromFirstHit(const RayDifferential& ray, SurfaceInteraction* hit, Float tHit,
                                  const Scene& scene, IntegratorContext& ctx,
                                  Float* alpha) const = 0;

 protected:
  ~FirstHitRadiance() = default;
};

// The groups of a pixel's samples whose camera rays are traced together: samples [8 g, 8 g + 8),
// eight for the width of Embree's AVX2 packets. A pass that ends inside a group traces it whole.
inline constexpr int kCameraRayGroup = 8;

class PixelSampleIntegrator : public Integrator {
 public:
  // The sampler's samples per pixel: in doubling passes of sample indices (progressive_render.h)
  // when options.afterPass or options.timeBudget is set, else in one pass of options.render's
  // sample range.
  ProgressiveResult render(const RenderInputs& in, Film& film,
                           const ProgressiveOptions& options) override;
  // One pass: samples [options.firstSample, options.endSample) of every pixel of the film's
  // bounds, or of the full image with splats on for an integrator whose pixelLight() is
  // Splatted. Rendering [0, a) then [a, b) into one film gives the same bits as [0, b).
  virtual RenderResult renderSamples(const RenderInputs& in, Film& film,
                                     const RenderOptions& options);
  // The radiance arriving along a camera ray; *alpha is set to 1 when the ray hits a surface and
  // 0 when it escapes.
  virtual Spectrum Li(const RayDifferential& ray, const Scene& scene, IntegratorContext& ctx,
                      Float* alpha) const = 0;
  // The scene build warns for integrators that do not attenuate every ray by Volume regions
  // (photons, gather rays, light subpaths would cross the volume unattenuated).
  virtual VolumeRegionLight volumeRegionLight() const {
    return VolumeRegionLight::CameraRayAndDirect;
  }
  // Camera ray differentials are scaled by 1/sqrt(samples per pixel) (pbrt 3e §1.4.3), and by no
  // less than this (pbrt-v3's sampler integrators keep 1/8). 0 by default.
  void setMinDifferentialScale(Float scale) { minDifferentialScale_ = scale; }
  Float minDifferentialScale() const { return minDifferentialScale_; }

 protected:
  // How renderPixelSamples takes a pass; sampleLoop gives what suits most integrators, and a
  // subclass that needs otherwise changes it in its renderSamples.
  struct SampleLoop {
    Bounds2i pixels;                // the pixels whose samples are taken
    SplatBuffer* splats = nullptr;  // IntegratorContext::splats
    bool rayDifferentials = false;  // camera rays carry differentials
    // Non-null: camera rays are traced in groups, and each path starts from its ray's hit.
    const FirstHitRadiance* firstHit = nullptr;
    // The sample indices the film takes; the others are traced and not kept (path guiding's
    // training beyond a sample range). -1: no bound.
    int filmFirstSample = -1, filmEndSample = -1;
  };
  // The film's pixel bounds, no splats, differentials where the scene's textures read them.
  SampleLoop sampleLoop(const RenderInputs& in, const Film& film) const;
  RenderResult renderPixelSamples(const RenderInputs& in, Film& film, const RenderOptions& options,
                                  const SampleLoop& loop) const;

 private:
  Float minDifferentialScale_ = 0;
};

}  // namespace candela
