#include "transport/specular_differentials.h"

namespace candela {

namespace {

// The rate of change of the shading normal along one image axis, by the chain rule through
// (u, v) (pbrt 2e §10.1.3).
Vector3f normalDerivative(const SurfaceInteraction& isect, Float dudImage, Float dvdImage) {
  return Vector3f(isect.shading.dndu) * dudImage + Vector3f(isect.shading.dndv) * dvdImage;
}

// Mirror direction wi = -wo + 2 (wo.n) n, differentiated: dwi = -dwo + 2 ((wo.n) dn + d(wo.n) n).
Vector3f reflectedOffset(const Vector3f& wo, const Vector3f& wi, const Vector3f& n,
                         const Vector3f& dwo, const Vector3f& dn) {
  Float dWoN = dot(dwo, n) + dot(wo, dn);
  return wi - dwo + 2 * (dn * dot(wo, n) + n * dWoN);
}

// Refracted direction wi = -eta wo + mu n with mu = eta (wo.n) - |wi.n|, n on wo's side and eta
// the ratio of wo's index to wi's. (Derived here; the printed pbrt 2e listing's dmu is wrong, and
// pbrt-v3 corrected it to this.) From |wi.n|^2 = 1 - eta^2 + eta^2 (wo.n)^2,
// dmu = (eta - eta^2 (wo.n) / |wi.n|) d(wo.n).
Vector3f refractedOffset(const Vector3f& wo, const Vector3f& wi, const Vector3f& n, Float eta,
                         const Vector3f& dwo, const Vector3f& dn) {
  Float woN = dot(wo, n), wiN = std::abs(dot(wi, n));
  Float mu = eta * woN - wiN;
  Float dWoN = dot(dwo, n) + dot(wo, dn);
  Float dmu = (eta - eta * eta * woN / wiN) * dWoN;
  return wi - eta * dwo + (dn * mu + n * dmu);
}

}  // namespace

RayDifferential spawnSpecularRay(const SurfaceInteraction& isect, const BSDF& bsdf,
                                 const RayDifferential& incoming, const Vector3f& wi,
                                 bool transmission) {
  RayDifferential ray(isect.spawnRay(wi));
  // A refracted ray along the tangent plane has no defined derivative (|wi.n| divides below).
  if (!incoming.hasDifferentials || dot(wi, bsdf.shadingNormal()) == 0) return ray;
  const Vector3f& wo = isect.wo;
  // The bumped normal when the material bump-maps; its derivatives are the surface's.
  Vector3f n(bsdf.shadingNormal());
  Vector3f dndx = normalDerivative(isect, isect.dudx, isect.dvdx);
  Vector3f dndy = normalDerivative(isect, isect.dudy, isect.dvdy);
  // The offset rays' wo, as differences from the main ray's.
  Vector3f dwodx = -incoming.rxDirection - wo, dwody = -incoming.ryDirection - wo;
  ray.hasDifferentials = true;
  ray.rxOrigin = isect.p + isect.dpdx;
  ray.ryOrigin = isect.p + isect.dpdy;
  if (!transmission) {
    ray.rxDirection = reflectedOffset(wo, wi, n, dwodx, dndx);
    ray.ryDirection = reflectedOffset(wo, wi, n, dwody, dndy);
    return ray;
  }
  // bsdf.eta is the inside index with 1 outside; the shading normal points outside.
  Float eta = 1 / bsdf.eta;
  if (dot(wo, n) < 0) {
    eta = bsdf.eta;
    n = -n;
    dndx = -dndx;
    dndy = -dndy;
  }
  ray.rxDirection = refractedOffset(wo, wi, n, eta, dwodx, dndx);
  ray.ryDirection = refractedOffset(wo, wi, n, eta, dwody, dndy);
  return ray;
}

RayDifferential continueThrough(const SurfaceInteraction& isect, const RayDifferential& ray,
                                Float tMax) {
  Float tHit = ray.tMax;  // intersect shortened it to the hit
  RayDifferential next(isect.spawnRay(ray.d));
  next.tMax = tMax - tHit;
  if (ray.hasDifferentials)
    next = RayDifferential(next, Ray(ray.rxOrigin + ray.rxDirection * tHit, ray.rxDirection),
                           Ray(ray.ryOrigin + ray.ryDirection * tHit, ray.ryDirection));
  return next;
}

}  // namespace candela
