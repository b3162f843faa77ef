// Participating media (lrt draft ch. 12 "volume regions"; pbrt 2e ch. 11; pbrt 3e §11.3): at each
// point of world space, absorption σa and out-scattering σs per unit length, emission Le per unit
// length (the drafts' Lve) and a phase function. Both scene dialects build on this one interface:
// pbrt-v2's `Volume` regions (several aggregated) fill the scene's volume; pbrt-v3's named media
// sit on either side of shapes (MediumInterface). Integrators reach a medium only through this
// interface, and a scene without media holds none (null), so it pays nothing.
#pragma once

#include "core/bounds.h"
#include "core/ray.h"
#include "core/spectrum.h"
#include "media/phase_function.h"

namespace candela {

// The coefficients at one point (world units^-1).
struct MediumPoint {
  Spectrum sigmaA, sigmaS;
  Spectrum Le;  // emitted radiance per unit length
  Spectrum sigmaT() const { return sigmaA + sigmaS; }
};

class Medium {
 public:
  virtual ~Medium() = default;
  // Where the coefficients may be nonzero; outside it the medium is vacuum.
  virtual Bounds3f worldBound() const = 0;
  // The parametric range [*t0, *t1] of the ray (within [0, ray.tMax]) that lies in the medium's
  // extent; false when it misses.
  virtual bool intersectP(const Ray& ray, Float* t0, Float* t1) const = 0;
  // The coefficients at world point p at the given time.
  virtual MediumPoint at(const Point3f& p, Float time) const = 0;
  // The phase function at p (an aggregate of regions answers with the one of largest σs there).
  virtual PhaseFunction phase(const Point3f& p, Float time) const = 0;
  // The optical depth ∫ σt dt along ray(t) for t in [t0, t1] (t in the ray's parameter, ray.d of
  // any length). stepSize (world units) and offset (in [0, 1), the fraction of a step at which
  // the first sample sits) drive the ray marching that media without a closed form use (lrt draft
  // §12.3); media with a closed form ignore them.
  virtual Spectrum opticalDepth(const Ray& ray, Float t0, Float t1, Float stepSize,
                                Float offset) const;
  // An upper bound on σt (every channel) over the ray's segment [t0, t1]: the majorant of delta
  // and ratio tracking (pbrt 3e §15.2).
  virtual Spectrum majorant(const Ray& ray, Float t0, Float t1) const = 0;
  // Whether σa, σs and Le are the same everywhere inside worldBound (closed-form transmittance).
  virtual bool isHomogeneous() const { return false; }
  // Whether Le may be nonzero somewhere (false: Le is zero everywhere).
  virtual bool emits() const { return false; }
};

}  // namespace candela
