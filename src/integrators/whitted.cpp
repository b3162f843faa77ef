#include "integrators/whitted.h"

#include "transport/volume_transmittance.h"

namespace candela {

Spectrum WhittedIntegrator::directLight(const SurfaceInteraction& isect, const BSDF& bsdf,
                                        const Scene& scene, IntegratorContext& ctx) const {
  Spectrum l(0);
  for (const Light* light : scene.lights()) {
    Vector3f wi;
    Float pdf = 0;
    VisibilityTester vis;
    Spectrum li = light->sampleLi(isect, ctx.sampler.get2D(), &wi, &pdf, &vis);
    if (pdf == 0 || li.isBlack()) continue;
    Spectrum f = bsdf.f(isect.wo, wi);
    // The shadow ray last: it is the expensive test.
    if (!f.isBlack() && scene.unoccluded(vis, ctx.stats))
      l += f * li * volumeTransmittance(vis, scene, ctx) * (absDot(wi, bsdf.shadingNormal()) / pdf);
  }
  return l;
}

}  // namespace candela
