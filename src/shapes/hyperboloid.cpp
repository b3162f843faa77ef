#include "shapes/hyperboloid.h"

namespace candela {

namespace {

HyperboloidFit fitOf(const Point3f& p1, const Point3f& p2) {
  double a[3] = {p1.x, p1.y, p1.z}, b[3] = {p2.x, p2.y, p2.z};
  return fitHyperboloid(a, b);
}

}  // namespace

HyperboloidShape::HyperboloidShape(const Transform& objectToWorld, bool reverseOrientation,
                                   const Point3f& p1, const Point3f& p2, Float phiMaxDeg,
                                   HyperboloidNormal normal)
    : Quadric(objectToWorld, reverseOrientation),
      fit_(fitOf(p1, p2)),
      profile_(fit_.degenerate ? 0 : fit_.k, fit_.degenerate ? 0 : fit_.d, std::min(p1.z, p2.z),
               std::max(p1.z, p2.z)),
      zMin_(std::min(p1.z, p2.z)),
      zMax_(std::max(p1.z, p2.z)),
      phiMax_(phiMaxRadians(phiMaxDeg)),
      normal_(normal) {
  const double* a = fit_.p1;
  for (int i = 0; i < 3; ++i) delta_[i] = fit_.p2[i] - a[i];
  double dz = delta_[2];
  invDz_ = dz != 0 ? 1 / dz : 0;
  alpha_ = delta_[0] * delta_[0] + delta_[1] * delta_[1];
  beta_ = 2 * (a[0] * delta_[0] + a[1] * delta_[1]);
  gamma_ = a[0] * a[0] + a[1] * a[1];
  cross_ = a[0] * delta_[1] - a[1] * delta_[0];
  rMax_ = std::sqrt(profile_.maxRadiusSquared());
  // dp/du x dp/dv has the radial component phiMax rho dz (see geometryAt).
  crossPointsInward_ = dz < 0;
  objectArea_ = dz != 0 ? phiMax_ * profile_.areaPerRadian() : 0;
  setBoundingBall();
}

Bounds3f HyperboloidShape::objectBound() const {
  Float r = Float(rMax_);
  if (double(r) < rMax_) r = nextFloatUp(r);
  return Bounds3f(Point3f(-r, -r, Float(zMin_)), Point3f(r, r, Float(zMax_)));
}

void HyperboloidShape::lineCoefficients(const double o[3], const double d[3], double* a, double* b,
                                        double* c) const {
  // F = x^2 + y^2 - k z^2 - d along the line.
  double k = fit_.k;
  *a = d[0] * d[0] + d[1] * d[1] - k * d[2] * d[2];
  *b = 2 * (d[0] * o[0] + d[1] * o[1] - k * d[2] * o[2]);
  *c = o[0] * o[0] + o[1] * o[1] - k * o[2] * o[2] - fit_.d;
}

double HyperboloidShape::implicit(const double p[3], double* fErr, double grad[3]) const {
  double x2 = p[0] * p[0] + p[1] * p[1], kz2 = fit_.k * p[2] * p[2];
  *fErr = 10 * std::numeric_limits<double>::epsilon() * (x2 + std::abs(kz2) + std::abs(fit_.d));
  grad[0] = 2 * p[0];
  grad[1] = 2 * p[1];
  grad[2] = -2 * fit_.k * p[2];
  return x2 - kz2 - fit_.d;
}

void HyperboloidShape::segmentPoint(double v, double* x, double* y) const {
  *x = fit_.p1[0] + v * delta_[0];
  *y = fit_.p1[1] + v * delta_[1];
}

double HyperboloidShape::sweepAngle(const double p[3], double v) const {
  double rx, ry;
  segmentPoint(v, &rx, &ry);
  // 0 where the segment meets the axis.
  return azimuth(rx * p[0] + ry * p[1], rx * p[1] - ry * p[0]);
}

bool HyperboloidShape::clip(double p[3]) const {
  if (!(p[2] >= zMin_ && p[2] <= zMax_)) return false;
  double v = (p[2] - fit_.p1[2]) * invDz_;
  return phiMax_ >= 2 * std::numbers::pi || sweepAngle(p, v) <= phiMax_;
}

Quadric::LocalGeometry HyperboloidShape::geometryAt(const double p[3]) const {
  double z = p[2], v = (z - fit_.p1[2]) * invDz_;
  double phi = sweepAngle(p, v);
  LocalGeometry g;
  g.uv = Point2f(Float(phi / phiMax_), Float(v));
  // The radial direction; taken a little off the axis where the surface meets it (a cone's apex,
  // an ellipsoid's or two-sheet hyperboloid's pole; seed notes §23).
  double rho = std::hypot(p[0], p[1]), rhoMin = kAxisNudge * rMax_;
  double cx, cy;
  if (rho > 0) {
    cx = p[0] / rho;
    cy = p[1] / rho;
  } else {
    double rx, ry;
    segmentPoint(v, &rx, &ry);
    double len = std::hypot(rx, ry);
    double c = std::cos(phi), s = std::sin(phi);
    cx = len > 0 ? (rx * c - ry * s) / len : 1;
    cy = len > 0 ? (rx * s + ry * c) / len : 0;
  }
  double r = std::max(rho, rhoMin);
  if (!(r > 0)) r = 1e-30;
  double xg = r * cx, yg = r * cy;
  // p(u, v) = rho(z) (cos theta, sin theta, 0) + z e_z with z = z1 + v dz and
  // theta = theta_seg(v) + u phiMax: dp/dv = dz rho' e_r + rho w e_theta + dz e_z, where
  // rho' = k z / rho and w = dtheta_seg/dv = cross / R(v).
  double dz = delta_[2], k = fit_.k;
  double rhoP = k * z / r;
  double R = (alpha_ * v + beta_) * v + gamma_;
  double w = R > 0 ? cross_ / R : 0;
  double wP = R > 0 ? -cross_ * (2 * alpha_ * v + beta_) / (R * R) : 0;
  double radial = dz * rhoP, tangential = r * w;
  double dvx = radial * cx - tangential * cy, dvy = radial * cy + tangential * cx;
  g.dpdu = Vector3f(Float(-phiMax_ * yg), Float(phiMax_ * xg), 0);
  g.d2Pduu = Vector3f(Float(-phiMax_ * phiMax_ * xg), Float(-phiMax_ * phiMax_ * yg), 0);
  if (normal_ == HyperboloidNormal::SegmentAsPbrt) {
    // pbrt's derivatives: the segment's direction turned by phi, and no second derivative in v.
    double c = std::cos(phi), s = std::sin(phi);
    double sx = delta_[0] * c - delta_[1] * s, sy = delta_[0] * s + delta_[1] * c;
    g.dpdv = Vector3f(Float(sx), Float(sy), Float(dz));
    g.d2Pduv = Vector3f(Float(-phiMax_ * sy), Float(phiMax_ * sx), 0);
    g.d2Pdvv = Vector3f(0, 0, 0);
    return g;
  }
  g.dpdv = Vector3f(Float(dvx), Float(dvy), Float(dz));
  g.d2Pduv = Vector3f(Float(-phiMax_ * dvy), Float(phiMax_ * dvx), 0);
  // d2p/dv2 = (dz^2 rho'' - rho w^2) e_r + (2 dz rho' w + rho w') e_theta, rho'' = (k -
  // rho'^2)/rho.
  double rhoPP = (k - rhoP * rhoP) / r;
  double vr = dz * dz * rhoPP - r * w * w, vt = 2 * dz * rhoP * w + r * wP;
  g.d2Pdvv = Vector3f(Float(vr * cx - vt * cy), Float(vr * cy + vt * cx), 0);
  return g;
}

void HyperboloidShape::sampleObject(const Point2f& u, double p[3]) const {
  double z = profile_.heightAtAreaFraction(u.x);
  double v = (z - fit_.p1[2]) * invDz_;
  double rx, ry;
  segmentPoint(v, &rx, &ry);
  double theta = azimuth(rx, ry) + double(u.y) * phiMax_;
  double rho = std::sqrt(std::max(0.0, profile_.radiusSquared(z)));
  p[0] = rho * std::cos(theta);
  p[1] = rho * std::sin(theta);
  p[2] = z;
}

std::unique_ptr<Shape> createHyperboloidShape(const Transform& objectToWorld,
                                              bool reverseOrientation, const ParamSet& params,
                                              HyperboloidNormal normal) {
  Point3f p1 = params.getOnePoint3f("p1", Point3f(0, 0, 0));
  Point3f p2 = params.getOnePoint3f("p2", Point3f(1, 1, 1));
  for (auto [name, p] : {std::pair{"p1", p1}, std::pair{"p2", p2}})
    for (Float c : {p.x, p.y, p.z}) params.requireInRange(name, c, ValueRange::finite(), FileLoc());
  if (p1.z == p2.z)
    throw SceneError(params.locationOf("p2", FileLoc()),
                     "hyperboloid \"p1\" and \"p2\" must differ in z (use a disk with an "
                     "\"innerradius\" for a flat ring)");
  return std::make_unique<HyperboloidShape>(objectToWorld, reverseOrientation, p1, p2,
                                            quadricPhiMax(params), normal);
}

}  // namespace candela
