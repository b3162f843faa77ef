#include "shapes/cone.h"

namespace candela {

ConeShape::ConeShape(const Transform& objectToWorld, bool reverseOrientation, Float height,
                     Float radius, Float phiMaxDeg)
    : Quadric(objectToWorld, reverseOrientation),
      height_(height),
      radius_(radius),
      phiMax_(phiMaxRadians(phiMaxDeg)),
      k_(height != 0 ? (double(radius) / height) * (double(radius) / height) : 0) {
  // The lateral area phiMax r s / 2 with slant height s = sqrt(r^2 + h^2).
  objectArea_ = height_ != 0 ? 0.5 * phiMax_ * radius_ * std::hypot(radius_, height_) : 0;
  // dp/dv = (-r cos phi, -r sin phi, h): dp/du x dp/dv has the sign of h radially.
  crossPointsInward_ = height_ < 0;
  setBoundingBall();
}

Bounds3f ConeShape::objectBound() const {
  Float r = Float(radius_), h = Float(height_);
  return Bounds3f(Point3f(-r, -r, std::min(Float(0), h)), Point3f(r, r, std::max(Float(0), h)));
}

void ConeShape::lineCoefficients(const double o[3], const double d[3], double* a, double* b,
                                 double* c) const {
  // x^2 + y^2 - (r/h)^2 (z - h)^2 along the line (lrt draft §3.5.1).
  double oz = o[2] - height_;
  *a = d[0] * d[0] + d[1] * d[1] - k_ * d[2] * d[2];
  *b = 2 * (d[0] * o[0] + d[1] * o[1] - k_ * d[2] * oz);
  *c = o[0] * o[0] + o[1] * o[1] - k_ * oz * oz;
}

double ConeShape::implicit(const double p[3], double* fErr, double grad[3]) const {
  double x2 = p[0] * p[0] + p[1] * p[1], dz = p[2] - height_, z2 = k_ * dz * dz;
  *fErr = 6 * std::numeric_limits<double>::epsilon() * (x2 + z2);
  grad[0] = 2 * p[0];
  grad[1] = 2 * p[1];
  grad[2] = -2 * k_ * dz;
  // Outward (away from the axis) for h < 0 too: the radial components decide.
  return x2 - z2;
}

bool ConeShape::clip(double p[3]) const {
  // v = z / h in [0, 1]: the nappe between base and apex; the other nappe of the double cone is
  // cut away here too.
  double v = p[2] / height_;
  if (!(v >= 0 && v <= 1)) return false;
  return phiMax_ >= 2 * std::numbers::pi || azimuth(p[0], p[1]) <= phiMax_;
}

Quadric::LocalGeometry ConeShape::geometryAt(const double p[3]) const {
  double v = p[2] / height_;
  double rho = std::sqrt(p[0] * p[0] + p[1] * p[1]);
  double phi = azimuth(p[0], p[1]);
  double cosPhi = std::cos(phi), sinPhi = std::sin(phi);
  LocalGeometry g;
  g.uv = Point2f(Float(phi / phiMax_), Float(v));
  // The draft's dp/dv = (-x / (1 - v), -y / (1 - v), h) is 0/0 at the apex, and dp/du vanishes
  // there: with cos phi, sin phi in place of the quotients and dp/du taken a little below the
  // apex, both stay finite (seed notes §23). The draft prints +y / (1 - v): a typo (§24).
  double rhoG = std::max(rho, kAxisNudge * radius_);
  double xg = rhoG * cosPhi, yg = rhoG * sinPhi;
  g.dpdu = Vector3f(Float(-phiMax_ * yg), Float(phiMax_ * xg), 0);
  g.dpdv = Vector3f(Float(-radius_ * cosPhi), Float(-radius_ * sinPhi), Float(height_));
  g.d2Pduu = Vector3f(Float(-phiMax_ * phiMax_ * xg), Float(-phiMax_ * phiMax_ * yg), 0);
  // d/dv of dp/du = phiMax (r sin phi, -r cos phi, 0), the draft's phiMax / (1 - v) (y, -x, 0).
  g.d2Pduv = Vector3f(Float(phiMax_ * radius_ * sinPhi), Float(-phiMax_ * radius_ * cosPhi), 0);
  return g;
}

void ConeShape::sampleObject(const Point2f& u, double p[3]) const {
  // The area element is proportional to the distance from the axis, r (1 - v): 1 - v = sqrt(u)
  // inverts its CDF.
  double s = std::sqrt(double(u.x)), phi = u.y * phiMax_;
  p[0] = radius_ * s * std::cos(phi);
  p[1] = radius_ * s * std::sin(phi);
  p[2] = height_ * (1 - s);
}

std::unique_ptr<Shape> createConeShape(const Transform& objectToWorld, bool reverseOrientation,
                                       const ParamSet& params) {
  Float radius = params.getOneFloat("radius", 1, ValueRange::positive(), FileLoc());
  Float height = params.getOneFloat("height", 1, ValueRange::finite(), FileLoc());
  if (height == 0)
    throw SceneError(params.locationOf("height", FileLoc()), "cone \"height\" must not be 0");
  return std::make_unique<ConeShape>(objectToWorld, reverseOrientation, height, radius,
                                     quadricPhiMax(params));
}

}  // namespace candela
