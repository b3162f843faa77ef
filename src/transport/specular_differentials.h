// The ray leaving a perfect specular reflection or refraction, with ray differentials carried
// along so that textures seen in mirrors and through glass are still filtered (pbrt 2e §10.1.3):
// the offset rays' hit points come from the tangent-plane differentials, and their directions
// from differentiating the reflection and refraction formulas with respect to image position.
#pragma once

#include "core/interaction.h"
#include "reflection/bsdf.h"
#include "samplers/sampler.h"

namespace candela {

// isect must have had computeDifferentials(incoming) called. wi is the direction the BSDF
// sampled; transmission says whether it was refracted through the surface.
RayDifferential spawnSpecularRay(const SurfaceInteraction& isect, const BSDF& bsdf,
                                 const RayDifferential& incoming, const Vector3f& wi,
                                 bool transmission);

// The ray continued straight through a surface that does not scatter (a shape without a
// material), as the same ray: tMax is the ray's extent before it hit isect, and the result keeps
// what remains of it and the differentials, the offset rays moved along by the same t (as
// pbrt-v4's SkipIntersection), so textures behind the surface are still filtered and yon still
// clips.
RayDifferential continueThrough(const SurfaceInteraction& isect, const RayDifferential& ray,
                                Float tMax);

// Light arriving by perfect specular reflection, then transmission, at isect toward isect.wo:
// each is one deterministic direction, so one sample of each gives the exact recursive term
// (pbrt 2e §1.3.6). radiance(ray) is the radiance along the spawned ray (with differentials).
template <typename Radiance>
Spectrum specularlyScattered(const SurfaceInteraction& isect, const BSDF& bsdf,
                             const RayDifferential& incoming, Sampler& sampler,
                             const Radiance& radiance) {
  Spectrum l(0);
  for (bool transmission : {false, true}) {
    int flags = kSpecular | (transmission ? kTransmission : kReflection);
    Vector3f wi;
    Float pdf;
    Spectrum f = bsdf.sampleF(isect.wo, &wi, sampler.get1D(), sampler.get2D(), &pdf, flags);
    Float cosTerm = absDot(wi, bsdf.shadingNormal());
    if (pdf > 0 && !f.isBlack() && cosTerm != 0)
      l +=
          f * radiance(spawnSpecularRay(isect, bsdf, incoming, wi, transmission)) * (cosTerm / pdf);
  }
  return l;
}

}  // namespace candela
