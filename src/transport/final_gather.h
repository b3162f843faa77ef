// Final gathering (pbrt 2e §15.6.3): the indirect light at a shading point is estimated by tracing
// gather rays and reading, where each lands, the radiance of the nearest radiance photon. Two
// strategies, combined with multiple importance sampling by the power heuristic: directions
// sampled from the BSDF, and directions sampled in cones around the incident directions of nearby
// indirect photons (where indirect light actually comes from).
#pragma once

#include <span>

#include "reflection/bsdf.h"
#include "transport/integrator_context.h"
#include "transport/photon_map.h"

namespace candela {

// The photon-guided strategy's pdf: an equal mixture of uniform cones of half-angle acos(cosAngle)
// around each of the given unit directions.
class PhotonConeDirections {
 public:
  PhotonConeDirections(std::span<const Vector3f> axes, Float cosAngle)
      : axes_(axes), cosAngle_(cosAngle) {}
  bool empty() const { return axes_.empty(); }
  // Samples a cone with u, a direction in it with u2; *cone is the cone used.
  Vector3f sample(Float u, const Point2f& u2, int* cone) const;
  // The mixture density at w (solid angle). knownCone, when >= 0, is a cone w was sampled in:
  // it counts without the containment test, so rounding at the cone's rim cannot make the density
  // of a sampled direction 0 (the reason for the book's ".999 cos" test, which instead adds cones
  // that cannot have produced w).
  Float pdf(const Vector3f& w, int knownCone = -1) const;

 private:
  std::span<const Vector3f> axes_;
  Float cosAngle_;
};

struct FinalGatherSettings {
  int samplesPerStrategy = 16;         // pbrt-v2 splits finalgathersamples evenly between the two
  Float cosGatherAngle = 0.98480775f;  // cos 10 degrees
  int nDirectionPhotons = 50;          // indirect photons whose directions guide sampling
  int maxSpecularDepth = 5;            // specular bounces a gather ray may follow
};

// The incident directions of the nDirectionPhotons indirect photons nearest p, in the arena.
std::span<const Vector3f> nearbyPhotonDirections(const PhotonMap& indirect, const Point3f& p,
                                                 int count, MemoryArena& arena);

// Radiance arriving at the origin of ray from the radiance photons, after following up to
// maxSpecularDepth perfectly specular bounces (which carry no radiance photons).
Spectrum gatherRayRadiance(const RayDifferential& ray, const RadiancePhotonMap& radiance,
                           const Scene& scene, IntegratorContext& ctx, int maxSpecularDepth);

// The indirect radiance reflected toward it.wo: samplesPerStrategy rays from each strategy.
Spectrum finalGather(const SurfaceInteraction& it, const BSDF& bsdf,
                     const PhotonConeDirections& cones, const RadiancePhotonMap& radiance,
                     const Scene& scene, IntegratorContext& ctx, const FinalGatherSettings& s);

}  // namespace candela
