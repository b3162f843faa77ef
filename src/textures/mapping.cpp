#include "textures/mapping.h"

namespace candela {

TexCoord2D UVMapping2D::map(const SurfaceInteraction& si) const {
  TexCoord2D c;
  c.st = Point2f(su_ * si.uv.x + du_, sv_ * si.uv.y + dv_);
  c.dsdx = su_ * si.dudx;
  c.dsdy = su_ * si.dudy;
  c.dtdx = sv_ * si.dvdx;
  c.dtdy = sv_ * si.dvdy;
  return c;
}

namespace {

// Angle phi of (x, y) in [0, 2pi), and its differential for a displacement d of the point.
Float phiOf(const Vector3f& q) {
  Float phi = std::atan2(q.y, q.x);
  return phi < 0 ? phi + 2 * kPi : phi;
}
Float dPhi(const Vector3f& q, const Vector3f& d) {
  Float rho2 = q.x * q.x + q.y * q.y;
  return rho2 > 0 ? (q.x * d.y - q.y * d.x) / rho2 : 0;
}

// Differential of theta = atan2(rho, z) for a displacement d. On the axis (rho = 0) theta grows
// with any sideways motion, so its size is the sideways length over r.
Float dTheta(const Vector3f& q, const Vector3f& d) {
  Float rho = std::sqrt(q.x * q.x + q.y * q.y), r2 = q.lengthSquared();
  if (r2 == 0) return 0;
  if (rho == 0) return std::sqrt(d.x * d.x + d.y * d.y) / std::sqrt(r2);
  return (q.z * (q.x * d.x + q.y * d.y) / rho - rho * d.z) / r2;
}

// Differential of z / r for a displacement d.
Float dUnitZ(const Vector3f& q, const Vector3f& d) {
  Float r2 = q.lengthSquared();
  if (r2 == 0) return 0;
  Float r = std::sqrt(r2);
  return d.z / r - q.z * dot(q, d) / (r2 * r);
}

}  // namespace

TexCoord2D SphericalMapping2D::map(const SurfaceInteraction& si) const {
  Vector3f q(worldToTexture_(si.p));
  Vector3f qx = worldToTexture_(si.dpdx), qy = worldToTexture_(si.dpdy);
  TexCoord2D c;
  if (q.lengthSquared() == 0) return c;  // the centre: every direction at once
  Float theta = std::atan2(std::sqrt(q.x * q.x + q.y * q.y), q.z);
  c.st = Point2f(theta * kInvPi, phiOf(q) * kInv2Pi);
  c.dsdx = dTheta(q, qx) * kInvPi;
  c.dsdy = dTheta(q, qy) * kInvPi;
  c.dtdx = dPhi(q, qx) * kInv2Pi;
  c.dtdy = dPhi(q, qy) * kInv2Pi;
  return c;
}

TexCoord2D CylindricalMapping2D::map(const SurfaceInteraction& si) const {
  Vector3f q(worldToTexture_(si.p));
  Vector3f qx = worldToTexture_(si.dpdx), qy = worldToTexture_(si.dpdy);
  TexCoord2D c;
  if (q.lengthSquared() == 0) return c;
  c.st = Point2f((kPi + std::atan2(q.y, q.x)) * kInv2Pi, q.z / q.length());
  c.dsdx = dPhi(q, qx) * kInv2Pi;
  c.dsdy = dPhi(q, qy) * kInv2Pi;
  c.dtdx = dUnitZ(q, qx);
  c.dtdy = dUnitZ(q, qy);
  return c;
}

TexCoord2D PlanarMapping2D::map(const SurfaceInteraction& si) const {
  Vector3f q(worldToTexture_(si.p));
  Vector3f qx = worldToTexture_(si.dpdx), qy = worldToTexture_(si.dpdy);
  TexCoord2D c;
  c.st = Point2f(ds_ + dot(q, vs_), dt_ + dot(q, vt_));
  c.dsdx = dot(qx, vs_);
  c.dsdy = dot(qy, vs_);
  c.dtdx = dot(qx, vt_);
  c.dtdy = dot(qy, vt_);
  return c;
}

TexCoord3D TextureMapping3D::map(const SurfaceInteraction& si) const {
  return TexCoord3D{worldToTexture_(si.p), worldToTexture_(si.dpdx), worldToTexture_(si.dpdy)};
}

}  // namespace candela
