#include "materials/bump.h"

#include "materials/material.h"

namespace candela {

Float bumpStepU(const SurfaceInteraction& si) {
  Float du = Float(0.5) * (std::abs(si.dudx) + std::abs(si.dudy));
  return du == 0 ? Float(0.01) : du;
}

Float bumpStepV(const SurfaceInteraction& si) {
  Float dv = Float(0.5) * (std::abs(si.dvdx) + std::abs(si.dvdy));
  return dv == 0 ? Float(0.01) : dv;
}

namespace {

// The point moved by `step` along the shading tangent dpdt in the parameter direction `axis`
// (0 = u, 1 = v), for evaluating the displacement there (lrt draft §10.10).
SurfaceInteraction shifted(const SurfaceInteraction& si, int axis, Float step) {
  SurfaceInteraction e = si;
  const Vector3f& dpdt = axis == 0 ? si.shading.dpdu : si.shading.dpdv;
  const Normal3f& dndt = axis == 0 ? si.shading.dndu : si.shading.dndv;
  e.p = si.p + step * dpdt;
  e.uv = si.uv + (axis == 0 ? Vector2f(step, 0) : Vector2f(0, step));
  Normal3f n = si.shading.n + step * dndt;
  if (n.lengthSquared() > 0) e.shading.n = normalize(n);
  return e;
}

}  // namespace

SurfaceInteraction bump(const Texture<Float>& displacement, const SurfaceInteraction& si) {
  Float du = bumpStepU(si), dv = bumpStepV(si);
  Float d = displacement.evaluate(si);
  Float dU = displacement.evaluate(shifted(si, 0, du));
  Float dV = displacement.evaluate(shifted(si, 1, dv));
  Vector3f n(si.shading.n);
  Vector3f dpdu = si.shading.dpdu + (dU - d) / du * n + d * Vector3f(si.shading.dndu);
  Vector3f dpdv = si.shading.dpdv + (dV - d) / dv * n + d * Vector3f(si.shading.dndv);
  SurfaceInteraction r = si;
  // Not authoritative: the bumped normal is turned to the geometric side (lrt draft §10.10).
  r.setShadingGeometry(dpdu, dpdv, si.shading.dndu, si.shading.dndv, false);
  return r;
}

const SurfaceInteraction& Material::bumpedPoint(const SurfaceInteraction& si,
                                                BumpedPointStorage* storage) const {
  return storage->emplace(bump(*bump_, si));
}

}  // namespace candela
