#include "shapes/shape.h"

namespace candela {

Interaction Shape::sample(const Interaction& ref, const Point2f& u, Float* pdf) const {
  Interaction it = sample(u, pdf);
  Vector3f wi = it.p - ref.p;
  Float dist2 = wi.lengthSquared();
  if (dist2 == 0) {
    *pdf = 0;
    return it;
  }
  wi = normalize(wi);
  // Area density to solid angle: dA cos(theta) / r^2 = dw.
  Float cosTheta = absDot(it.n, -wi);
  *pdf = cosTheta > 0 ? *pdf * dist2 / cosTheta : 0;
  if (std::isinf(*pdf)) *pdf = 0;
  return it;
}

Interaction Shape::sampleFrom(const Interaction& ref, const Point2f& u, Float* pdf,
                              Vector3f* wi) const {
  Interaction it = sample(ref, u, pdf);
  Vector3f d = it.p - ref.p;
  if (*pdf == 0 || d.lengthSquared() == 0)
    *pdf = 0;
  else
    *wi = normalize(d);
  return it;
}

Float Shape::pdf(const Interaction& ref, const Vector3f& wi) const {
  Ray ray = ref.spawnRay(wi);
  Float tHit;
  SurfaceInteraction isect;
  if (!intersect(ray, &tHit, &isect)) return 0;
  Float cosTheta = absDot(isect.n, -wi);
  if (cosTheta == 0) return 0;
  Float pdf = distanceSquared(ref.p, isect.p) / (cosTheta * area());
  return std::isinf(pdf) ? 0 : pdf;
}

}  // namespace candela
