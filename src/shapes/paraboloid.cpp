#include "shapes/paraboloid.h"

namespace candela {

ParaboloidShape::ParaboloidShape(const Transform& objectToWorld, bool reverseOrientation,
                                 Float radius, Float zMin, Float zMax, Float phiMaxDeg)
    : Quadric(objectToWorld, reverseOrientation),
      radius_(radius),
      zMax_(std::max(zMin, zMax)),
      phiMax_(phiMaxRadians(phiMaxDeg)) {
  zMin_ = zMax_ > 0 ? clamp(double(std::min(zMin, zMax)), 0.0, zMax_) : zMax_;
  q_ = zMax_ > 0 ? radius_ * radius_ / zMax_ : 0;
  // A surface of revolution: phiMax times the integral of rho sqrt(1 + rho'(z)^2) dz, with
  // rho^2 = q z: phiMax (2 / 3q) [(q z + q^2/4)^(3/2)] from zMin to zMax (pbrt 3e §3.5.2's
  // closed form, rewritten).
  objectArea_ = q_ > 0 ? phiMax_ * (2 / (3 * q_)) * (cdf(zMax_) - cdf(zMin_)) : 0;
  setBoundingBall();
}

double ParaboloidShape::cdf(double z) const {
  double w = q_ * z + 0.25 * q_ * q_;
  return w * std::sqrt(w);
}

Bounds3f ParaboloidShape::objectBound() const {
  Float r = Float(radius_);
  return Bounds3f(Point3f(-r, -r, Float(zMin_)), Point3f(r, r, Float(zMax_)));
}

void ParaboloidShape::lineCoefficients(const double o[3], const double d[3], double* a, double* b,
                                       double* c) const {
  // x^2 + y^2 - q z along the line (lrt draft §3.5.2, scaled by r^2 / zMax).
  *a = d[0] * d[0] + d[1] * d[1];
  *b = 2 * (d[0] * o[0] + d[1] * o[1]) - q_ * d[2];
  *c = o[0] * o[0] + o[1] * o[1] - q_ * o[2];
}

double ParaboloidShape::implicit(const double p[3], double* fErr, double grad[3]) const {
  double x2 = p[0] * p[0] + p[1] * p[1], qz = q_ * p[2];
  *fErr = 4 * std::numeric_limits<double>::epsilon() * (x2 + std::abs(qz));
  grad[0] = 2 * p[0];
  grad[1] = 2 * p[1];
  grad[2] = -q_;  // away from the axis and down: out of the bowl
  return x2 - qz;
}

bool ParaboloidShape::clip(double p[3]) const {
  if (p[2] < zMin_ || p[2] > zMax_) return false;
  return phiMax_ >= 2 * std::numbers::pi || azimuth(p[0], p[1]) <= phiMax_;
}

Quadric::LocalGeometry ParaboloidShape::geometryAt(const double p[3]) const {
  double phi = azimuth(p[0], p[1]);
  double cosPhi = std::cos(phi), sinPhi = std::sin(phi);
  LocalGeometry g;
  g.uv = Point2f(Float(phi / phiMax_), Float((p[2] - zMin_) / (zMax_ - zMin_)));
  // dp/dv = (zMax - zMin) (x / 2z, y / 2z, 1) (the draft prints x / z: a missing 1/2, seed notes
  // §24). x / 2z = cos phi q / (2 rho) grows without bound at the apex; the tangents are taken a
  // little off it, where rho = kAxisNudge r.
  double rho = std::max(std::sqrt(p[0] * p[0] + p[1] * p[1]), kAxisNudge * radius_);
  double dzdv = zMax_ - zMin_, slope = q_ / (2 * rho);  // x / 2z = slope cos phi
  double xg = rho * cosPhi, yg = rho * sinPhi;
  g.dpdu = Vector3f(Float(-phiMax_ * yg), Float(phiMax_ * xg), 0);
  g.dpdv = Vector3f(Float(dzdv * slope * cosPhi), Float(dzdv * slope * sinPhi), Float(dzdv));
  g.d2Pduu = Vector3f(Float(-phiMax_ * phiMax_ * xg), Float(-phiMax_ * phiMax_ * yg), 0);
  g.d2Pduv =
      Vector3f(Float(-dzdv * phiMax_ * slope * sinPhi), Float(dzdv * phiMax_ * slope * cosPhi), 0);
  // d2x/dz2 = -x / 4z^2 = -slope^2 cos phi / rho.
  double curv = dzdv * dzdv * slope * slope / rho;
  g.d2Pdvv = Vector3f(Float(-curv * cosPhi), Float(-curv * sinPhi), 0);
  return g;
}

void ParaboloidShape::sampleObject(const Point2f& u, double p[3]) const {
  double c = (1 - double(u.x)) * cdf(zMin_) + double(u.x) * cdf(zMax_);
  double w = std::cbrt(c * c);  // c^(2/3) = q z + q^2/4
  double z = clamp((w - 0.25 * q_ * q_) / q_, zMin_, zMax_);
  double rho = std::sqrt(q_ * z), phi = u.y * phiMax_;
  p[0] = rho * std::cos(phi);
  p[1] = rho * std::sin(phi);
  p[2] = z;
}

std::unique_ptr<Shape> createParaboloidShape(const Transform& objectToWorld,
                                             bool reverseOrientation, const ParamSet& params) {
  Float radius = params.getOneFloat("radius", 1, ValueRange::positive(), FileLoc());
  Float zMin = params.getOneFloat("zmin", 0, ValueRange::finite(), FileLoc());
  Float zMax = params.getOneFloat("zmax", 1, ValueRange::finite(), FileLoc());
  if (!(std::max(zMin, zMax) > 0))
    throw SceneError(params.locationOf("zmax", FileLoc()),
                     "paraboloid \"zmax\" must be positive, found " + std::to_string(zMax));
  return std::make_unique<ParaboloidShape>(objectToWorld, reverseOrientation, radius, zMin, zMax,
                                           quadricPhiMax(params));
}

}  // namespace candela
