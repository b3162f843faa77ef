#include "core/interaction.h"

namespace candela {

SurfaceInteraction::SurfaceInteraction(const Point3f& p_, const Vector3f& pError_,
                                       const Point2f& uv_, const Vector3f& wo_,
                                       const Vector3f& dpdu_, const Vector3f& dpdv_,
                                       const Normal3f& dndu_, const Normal3f& dndv_, Float time_,
                                       bool flipNormal)
    : SurfaceInteraction(p_, pError_, uv_, wo_, dpdu_, dpdv_, dndu_, dndv_, time_,
                         Normal3f(normalize(cross(dpdu_, dpdv_))) * (flipNormal ? -1 : 1)) {}

void SurfaceInteraction::setShadingGeometry(const Vector3f& dpdus, const Vector3f& dpdvs,
                                            const Normal3f& dndus, const Normal3f& dndvs,
                                            bool orientationIsAuthoritative) {
  Vector3f c = cross(dpdus, dpdvs);
  if (c.lengthSquared() > 0) {
    shading.n = Normal3f(normalize(c));
    if (orientationIsAuthoritative)
      n = faceForward(n, Vector3f(shading.n));
    else
      shading.n = faceForward(shading.n, Vector3f(n));
  }
  shading.dpdu = dpdus;
  shading.dpdv = dpdvs;
  shading.dndu = dndus;
  shading.dndv = dndvs;
}

void SurfaceInteraction::computeDifferentials(const RayDifferential& ray) const {
  auto reset = [&] {
    dudx = dvdx = dudy = dvdy = 0;
    dpdx = dpdy = Vector3f();
  };
  if (!ray.hasDifferentials) return reset();
  // Intersect the offset rays with the tangent plane n.p + d = 0.
  Float d = -dot(n, Vector3f(p));
  Float denX = dot(n, ray.rxDirection), denY = dot(n, ray.ryDirection);
  if (denX == 0 || denY == 0) return reset();
  Float tx = (-dot(n, Vector3f(ray.rxOrigin)) - d) / denX;
  Float ty = (-dot(n, Vector3f(ray.ryOrigin)) - d) / denY;
  if (!std::isfinite(tx) || !std::isfinite(ty)) return reset();
  dpdx = (ray.rxOrigin + ray.rxDirection * tx) - p;
  dpdy = (ray.ryOrigin + ray.ryDirection * ty) - p;
  // Least-squares-free 2x2 solve on the two axes best conditioned for this normal: drop the
  // axis of the largest normal component.
  int dim[2];
  if (std::abs(n.x) > std::abs(n.y) && std::abs(n.x) > std::abs(n.z))
    dim[0] = 1, dim[1] = 2;
  else if (std::abs(n.y) > std::abs(n.z))
    dim[0] = 0, dim[1] = 2;
  else
    dim[0] = 0, dim[1] = 1;
  Float a00 = dpdu[dim[0]], a01 = dpdv[dim[0]], a10 = dpdu[dim[1]], a11 = dpdv[dim[1]];
  Float det = a00 * a11 - a01 * a10;
  if (std::abs(det) < 1e-20f) {
    dudx = dvdx = dudy = dvdy = 0;
    return;
  }
  auto solve = [&](const Vector3f& b, Float* du, Float* dv) {
    Float b0 = b[dim[0]], b1 = b[dim[1]];
    *du = (a11 * b0 - a01 * b1) / det;
    *dv = (a00 * b1 - a10 * b0) / det;
    if (!std::isfinite(*du)) *du = 0;
    if (!std::isfinite(*dv)) *dv = 0;
  };
  solve(dpdx, &dudx, &dvdx);
  solve(dpdy, &dudy, &dvdy);
}

}  // namespace candela
