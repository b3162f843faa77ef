// Density estimation on photon maps (pbrt 2e §15.6.2; Silverman 1986): radiance and irradiance at a
// point from the nearest photons. The search radius shrinks to the farthest of the nUsed nearest
// photons, so the estimate adapts to the local photon density; this is where the bias of photon
// mapping comes from.
#pragma once

#include <span>

#include "core/memory.h"
#include "reflection/bsdf.h"
#include "transport/photon_map.h"

namespace candela {

struct DensityEstimate {
  int nUsed = 50;          // photons per estimate
  Float maxDist2 = 0.01f;  // squared largest search radius
  int nFilter = 0;  // the lrt draft's nfilter: brightest photons discarded from each estimate
};

// Simpson's kernel, (3 / pi) (1 - d^2 / r^2)^2 / r^2 for d < r: smooth, integrates to 1 over the
// disc (pbrt 2e §15.6.2).
inline Float simpsonKernel(Float dist2, Float radius2) {
  Float s = 1 - dist2 / radius2;
  return s > 0 ? Float(3) / kPi * s * s / radius2 : 0;
}

// Radiance reflected or transmitted toward wo by bsdf at p, from the map's photons:
// L = sum_j K(d_j) f(wo, wi_j) alpha_j / nPaths (pbrt 2e's LPhoton, evaluating f for every BSDF).
Spectrum photonRadiance(const PhotonMap& map, const Point3f& p, const Vector3f& wo,
                        const BSDF& bsdf, const DensityEstimate& est, MemoryArena& arena);

// Irradiance at p on the side n faces, with a constant kernel over the final search disc
// (pbrt 2e's EPhoton): photons arriving from behind n are not counted, nor the one on the rim
// that fixed the disc. excludeAtP leaves out photons exactly at p: a radiance photon's site is
// where a photon landed, and that photon is there because the site is, so counting it adds about
// one photon's worth to every estimate (pbrt-v2 counts it: in a room lit indirectly, with about
// ten photons in the default disc, final gathering came out 14% too bright, and 4.7 times at
// maxdist 0.02).
Spectrum photonIrradiance(const PhotonMap& map, const Point3f& p, const Normal3f& n,
                          const DensityEstimate& est, MemoryArena& arena, bool excludeAtP = false);

// How well a largest search radius suits a map, measured at its own photons' positions (where
// photons land, which is where lookups happen), up to `queries` of them spread evenly through it:
// the mean number of photons a lookup finds within the radius (at most nUsed), and the median
// distance of the nUsed-th nearest photon (the radius that would find them all at half the
// positions). The same map always gives the same figures.
struct SearchRadiusCheck {
  int queries = 0;
  double meanFound = 0;
  Float medianFullRadius = 0;
};
SearchRadiusCheck checkSearchRadius(const PhotonMap& map, const DensityEstimate& est,
                                    int queries = 256);

}  // namespace candela
