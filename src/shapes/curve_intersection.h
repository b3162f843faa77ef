// Ray-curve intersection without Embree, for the book's aggregates (pbrt 3e §3.7.2): the piece is
// taken to a frame where the ray runs along +z from the origin, halved recursively while its
// bound still meets the ray, to a depth where each part is straight to within a small fraction of
// the width, and each straight part is tested:
// - flat curves as a strip facing the ray: the closest point of the part's chord to the ray
//   gives s; the hit is the curve point at s when the ray passes within half the width, at that
//   point's depth (pbrt 3e's test);
// - ribbons likewise, but hit where the ray meets the band's plane at s, within half the width
//   of the curve across the band (pbrt 3e foreshortens the width instead);
// - round curves as the cone tangent to the spheres of radius r(s) centred on the chord (the
//   boundary of their union), cut where the curve's tangents at the part's ends are normal:
//   neighbouring parts meet on a shared plane, and the curve's own two ends stay open, as
//   Embree's round curves do.
// Computed in double.
#pragma once

#include "core/ray.h"

namespace candela {

class CurveShape;

struct CurveHit {
  Float t = 0;      // ray parameter
  Float s = 0;      // piece parameter
  Vector3f normal;  // round curves: the outward surface normal (world space, unit)
};

// The closest hit with t in (0, ray.tMax).
bool intersectCurvePiece(const CurveShape& shape, const Ray& ray, CurveHit* hit);

}  // namespace candela
