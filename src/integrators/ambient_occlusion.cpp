#include "integrators/ambient_occlusion.h"

#include "core/sampling.h"
#include "samplers/zero_two_sequence.h"

namespace candela {

namespace {

// A 32-bit binary fraction whose top bits are those of u in [0, 1).
uint32_t fractionBits(Float u) { return uint32_t(double(u) * 0x1p32); }

}  // namespace

Spectrum AmbientOcclusionIntegrator::Li(const RayDifferential& ray, const Scene& scene,
                                        IntegratorContext& ctx, Float* alpha) const {
  SurfaceInteraction isect;
  if (!scene.intersect(ray, &isect, ctx.stats)) {
    *alpha = 0;
    return Spectrum(0);
  }
  *alpha = 1;
  // The hemisphere is the geometric normal's, turned toward the viewer, so that no direction
  // starts into the surface whatever the shading normals do.
  Vector3f n(faceForward(isect.n, isect.wo)), s, t;
  coordinateSystem(n, &s, &t);
  // The directions are the first nSamples points of the (0,2)-sequence under a random digit
  // scramble (lrt draft §7.5.3): every point is uniform, so the estimate is unbiased, and each
  // power-of-two prefix is stratified. The scramble is one 2D sample of the pixel sample, so it
  // is a function of (pixel, sample index, seed) like every other random decision.
  Point2f scramble = ctx.sampler.get2D();
  uint32_t scrambleX = fractionBits(scramble.x), scrambleY = fractionBits(scramble.y);
  int clear = 0;
  double cosineSum = 0;  // pbrt-v3's estimate: cos / pdf over the clear directions
  for (int i = 0; i < nSamples_; ++i) {
    Point2f u(bitsToUnitFloat(vanDerCorputBits(uint32_t(i), scrambleX)),
              bitsToUnitFloat(sobol2Bits(uint32_t(i), scrambleY)));
    Vector3f local = cosSample_ ? sampleCosineHemisphere(u) : sampleUniformHemisphere(u);
    Vector3f w = s * local.x + t * local.y + n * local.z;
    Ray probe = isect.spawnRay(w);
    probe.tMax = maxDist_;
    if (scene.intersectP(probe, ctx.stats)) continue;
    ++clear;
    // cos / pdf: pi for cosine-weighted directions, 2 pi cos for uniform ones.
    cosineSum += cosSample_ ? kPi : 2 * kPi * double(local.z);
  }
  if (estimate_ == Estimate::UnoccludedCosine) return Spectrum(Float(cosineSum / nSamples_));
  return Spectrum(Float(clear) / Float(nSamples_));
}

}  // namespace candela
