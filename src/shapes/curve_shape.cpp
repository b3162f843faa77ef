#include "shapes/curve_shape.h"

#include <algorithm>
#include <cmath>

#include "shapes/curve_intersection.h"

namespace candela {

namespace {

// Some unit vector perpendicular to the unit vector a.
Vector3f anyPerpendicular(const Vector3f& a) {
  Vector3f b, c;
  coordinateSystem(a, &b, &c);
  return b;
}

}  // namespace

Normal3f slerpUnit(Float t, const Normal3f& a, const Normal3f& b) {
  Float cosTheta = std::clamp(dot(Vector3f(a), Vector3f(b)), Float(-1), Float(1));
  Float theta = std::acos(cosTheta);
  Float sinTheta = std::sin(theta);
  // Nearly parallel (or opposite, where the great circle is undefined): linear, renormalised.
  if (sinTheta < Float(1e-4)) {
    Normal3f n = a * (1 - t) + b * t;
    return n.lengthSquared() > 0 ? normalize(n) : a;
  }
  return a * (std::sin((1 - t) * theta) / sinTheta) + b * (std::sin(t * theta) / sinTheta);
}

Bounds3f CurveShape::worldBound() const {
  Bounds3f b;
  for (const Point3f& p : piece_.bezier.p) b = unionOf(b, p);
  // The convex hull holds the centre line; no surface point is farther than half the larger
  // end width from it (widths are linear in s), and the software test's tube parts reach a
  // little past their chords where they are cut at an angle: three quarters of the width.
  Float r = 0.75f * std::max(piece_.width[0], piece_.width[1]);
  Vector3f pad(r, r, r);
  return Bounds3f(b.pMin - pad, b.pMax + pad);
}

bool CurveShape::intersect(const Ray& ray, Float* tHit, SurfaceInteraction* isect) const {
  CurveHit hit;
  if (!intersectCurvePiece(*this, ray, &hit)) return false;
  *tHit = hit.t;
  if (isect) *isect = interactionAt(ray, hit.s, hit.t, hit.normal);
  return true;
}

Float CurveShape::area() const {
  Float length = 0;
  for (int i = 0; i < 3; ++i) length += (piece_.bezier.p[i + 1] - piece_.bezier.p[i]).length();
  return length * 0.5f * (piece_.width[0] + piece_.width[1]);
}

Interaction CurveShape::sample(const Point2f& u, Float* pdf) const {
  Vector3f tangent;
  Point3f c = evaluate(piece_.bezier, u.x, &tangent);
  Vector3f n = piece_.type == CurveType::Ribbon ? Vector3f(ribbonNormal(u.x))
                                                : anyPerpendicular(normalize(tangent));
  Vector3f side = normalize(cross(n, tangent));
  Interaction it;
  it.p = c + side * ((u.y - 0.5f) * widthAt(u.x));
  it.n = Normal3f(normalize(cross(tangent, side)));
  if (piece_.reverseOrientation) it.n = -it.n;
  Float a = area();
  *pdf = a > 0 ? 1 / a : 0;
  return it;
}

Normal3f CurveShape::ribbonNormal(Float s) const {
  return slerpUnit(s, piece_.normal[0], piece_.normal[1]);
}

SurfaceInteraction CurveShape::interactionAt(const Ray& ray, Float s, Float t,
                                             const Vector3f& surfaceNormal) const {
  Vector3f dcds;
  Point3f c = evaluate(piece_.bezier, s, &dcds);
  Float w = widthAt(s);
  Vector3f tangent = dcds.lengthSquared() > 0 ? normalize(dcds) : Vector3f(1, 0, 0);
  Point3f p = ray(t);
  Vector3f wo = -ray.d;
  if (wo.lengthSquared() > 0) wo = normalize(wo);

  // The surface normal before orientation: a flat curve faces the ray (the part of -d across
  // the tangent); a tube's normal points out from the centre line; a ribbon's follows its
  // normals' side.
  Vector3f n = surfaceNormal.lengthSquared() > 0 ? normalize(surfaceNormal) : Vector3f();
  switch (piece_.type) {
    case CurveType::Flat:
      n = wo - tangent * dot(wo, tangent);
      break;
    case CurveType::Cylinder:
      if (n == Vector3f()) n = p - c;
      if (dot(n, p - c) < 0) n = -n;
      break;
    case CurveType::Ribbon: {
      Vector3f nr(ribbonNormal(s));
      if (n == Vector3f()) n = nr;
      if (dot(n, nr) < 0) n = -n;
      break;
    }
  }
  n = n - tangent * dot(n, tangent);
  n = n.lengthSquared() > 0 ? normalize(n) : anyPerpendicular(tangent);

  // u along the segment (the piece covers [uMin, uMax] of it), v across the width.
  Float du = piece_.uMax - piece_.uMin;
  Vector3f dpdu = dcds / du;
  Vector3f side = normalize(cross(n, tangent));
  Vector3f dpdv = side * w;
  Float v = w > 0 ? std::clamp(0.5f + dot(p - c, side) / w, Float(0), Float(1)) : 0.5f;
  Point2f uv(lerp(s, piece_.uMin, piece_.uMax), v);
  // pbrt 3e §3.7.2's conservative bound, twice the width: hits on a strip that turns to face
  // each ray, or found by Embree's iterative curve tests, carry no tighter guarantee. Rays leave
  // a curve that far out, so none re-hits it (a refracted ray passes through it, as in pbrt).
  Vector3f pError(2 * w, 2 * w, 2 * w);
  // dpdu x dpdv points along n: dpdu x (n x tangent) = n |dpdu| for n perpendicular to it.
  return SurfaceInteraction(p, pError, uv, wo, dpdu, dpdv, Normal3f(), Normal3f(), ray.time,
                            piece_.reverseOrientation);
}

}  // namespace candela
