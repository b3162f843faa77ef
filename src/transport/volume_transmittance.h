// The one place where surface integrators meet the scene's volume (pbrt-v2 Volume regions): the
// transmittance of a shadow ray or a path segment. Scenes without a volume pay one null test;
// integrators otherwise know nothing of media.
#pragma once

#include "lights/light.h"
#include "transport/integrator_context.h"
#include "transport/volume_integrator.h"

namespace candela {

// The fraction of light that crosses ray's segment [0, ray.tMax] through scene.volume(); 1 when
// the scene has no volume or the renderer runs no volume integrator.
inline Spectrum volumeTransmittance(const Ray& ray, const Scene& scene, IntegratorContext& ctx) {
  if (!scene.volume() || !ctx.volumeIntegrator) return Spectrum(1);
  return ctx.volumeIntegrator->transmittance(ray, scene, ctx);
}

// The same for the whole segment of a visibility test (shading point to light sample; the
// medium needs no offset against self-intersection).
inline Spectrum volumeTransmittance(const VisibilityTester& vis, const Scene& scene,
                                    IntegratorContext& ctx) {
  if (!scene.volume() || !ctx.volumeIntegrator) return Spectrum(1);
  return ctx.volumeIntegrator->transmittance(Ray(vis.p0.p, vis.p1.p - vis.p0.p, 1, vis.p0.time),
                                             scene, ctx);
}

}  // namespace candela
