// What the light tree knows of a light or a group of lights (Conty Estevez & Kulla 2018,
// "Importance Sampling of Many Lights with Adaptive Tree Splitting"; pbrt 4e §12.6.1): where it is,
// how strongly it shines, and which way. The emitting surfaces' normals lie in the cone (w,
// cosThetaO), and each emits no further than acos(cosThetaE) from its normal (a Lambertian
// surface: 90°; a point source: every direction, its normal cone the whole sphere).
#pragma once

#include "core/bounds.h"
#include "core/direction_cone.h"
#include "core/spectrum.h"
#include "core/transform.h"

namespace candela {

struct LightBounds {
  Bounds3f bounds;
  // 4π times the largest radiant intensity (its luminance) the lights have in any direction,
  // summed: the same measure for points and surfaces, so that phi / d² bounds 4π times the
  // irradiance at distance d.
  Float phi = 0;
  Vector3f w{0, 0, 1};
  Float cosThetaO = -1;
  Float cosThetaE = 0;
  bool twoSided = false;

  DirectionCone normals() const { return {w, cosThetaO}; }
  // An estimate of the light the group sends to a point p with surface normal n (zero: a point in
  // a medium), 0 only where none of it can arrive: phi, times the cosine of the smallest angle at
  // which any emitter in the bounds could face p, times the cosine of the smallest angle to n
  // that any direction into the bounds makes, over the squared distance to the bounds' centre
  // (no less than the squared quarter-diagonal, so that points near or inside a group see it as
  // near but not as infinitely bright). Finite: at most the largest Float.
  Float importance(const Point3f& p, const Normal3f& n) const;
};

// The cone of world directions that the light-space cone about +z with the given cosine maps to
// under lightToWorld: exact for rotations and uniform scales, every direction for any other map
// (a shear or uneven scale makes the cone elliptic).
DirectionCone worldConeOfLightZ(const Transform& lightToWorld, Float cosTheta);

// The bounds of a point source at p of intensity I (its largest): phi = 4π I, emitting into the
// given cone of directions (cosThetaE = 1 beyond it: nothing) or every direction.
LightBounds pointSourceBounds(const Point3f& p, const Spectrum& intensity,
                              const DirectionCone& directions = DirectionCone::everyDirection());

// The bounds of two groups together; one without power adds nothing.
LightBounds unionOf(const LightBounds& a, const LightBounds& b);

// Conty Estevez & Kulla's measure of the directions a group emits into (their M_Ω, from its
// normal cone widened by the emission angle): what the tree's split cost weights a group's
// power and area by.
Float orientationMeasure(const LightBounds& b);

}  // namespace candela
