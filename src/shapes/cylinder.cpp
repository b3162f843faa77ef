#include "shapes/cylinder.h"

namespace candela {

CylinderShape::CylinderShape(const Transform& objectToWorld, bool reverseOrientation, Float radius,
                             Float zMin, Float zMax, Float phiMaxDeg)
    : Quadric(objectToWorld, reverseOrientation),
      radius_(radius),
      zMin_(std::min(zMin, zMax)),
      zMax_(std::max(zMin, zMax)),
      phiMax_(phiMaxRadians(phiMaxDeg)) {
  // (zMax - zMin) phiMax r (lrt draft §3.3.4).
  objectArea_ = (zMax_ - zMin_) * phiMax_ * radius_;
  setBoundingBall();
}

Bounds3f CylinderShape::objectBound() const {
  Float r = Float(radius_);
  return Bounds3f(Point3f(-r, -r, Float(zMin_)), Point3f(r, r, Float(zMax_)));
}

void CylinderShape::lineCoefficients(const double o[3], const double d[3], double* a, double* b,
                                     double* c) const {
  // x^2 + y^2 - r^2 along the line (lrt draft §3.3.2).
  *a = d[0] * d[0] + d[1] * d[1];
  *b = 2 * (d[0] * o[0] + d[1] * o[1]);
  *c = o[0] * o[0] + o[1] * o[1] - radius_ * radius_;
}

double CylinderShape::implicit(const double p[3], double* fErr, double grad[3]) const {
  double x2 = p[0] * p[0] + p[1] * p[1], r2 = radius_ * radius_;
  *fErr = 3 * std::numeric_limits<double>::epsilon() * (x2 + r2);
  grad[0] = 2 * p[0];
  grad[1] = 2 * p[1];
  grad[2] = 0;
  return x2 - r2;
}

bool CylinderShape::clip(double p[3]) const {
  // Back onto the surface (pbrt 3e §3.9.4), then the height range and the sweep.
  double rxy = std::sqrt(p[0] * p[0] + p[1] * p[1]);
  if (rxy > 0) {
    p[0] *= radius_ / rxy;
    p[1] *= radius_ / rxy;
  }
  if (p[2] < zMin_ || p[2] > zMax_) return false;
  return phiMax_ >= 2 * std::numbers::pi || azimuth(p[0], p[1]) <= phiMax_;
}

Quadric::LocalGeometry CylinderShape::geometryAt(const double p[3]) const {
  double phi = azimuth(p[0], p[1]);
  double x = radius_ * std::cos(phi), y = radius_ * std::sin(phi);
  LocalGeometry g;
  g.uv = Point2f(Float(phi / phiMax_), Float((p[2] - zMin_) / (zMax_ - zMin_)));
  g.dpdu = Vector3f(Float(-phiMax_ * y), Float(phiMax_ * x), 0);
  g.dpdv = Vector3f(0, 0, Float(zMax_ - zMin_));
  g.d2Pduu = Vector3f(Float(-phiMax_ * phiMax_ * x), Float(-phiMax_ * phiMax_ * y), 0);
  return g;
}

void CylinderShape::sampleObject(const Point2f& u, double p[3]) const {
  // z and phi uniform: the cylinder's area element is constant (lrt draft §15.6.1).
  double phi = u.y * phiMax_;
  p[0] = radius_ * std::cos(phi);
  p[1] = radius_ * std::sin(phi);
  p[2] = (1 - double(u.x)) * zMin_ + double(u.x) * zMax_;
}

std::unique_ptr<Shape> createCylinderShape(const Transform& objectToWorld, bool reverseOrientation,
                                           const ParamSet& params) {
  Float radius = params.getOneFloat("radius", 1, ValueRange::positive(), FileLoc());
  Float zMin = params.getOneFloat("zmin", -1, ValueRange::finite(), FileLoc());
  Float zMax = params.getOneFloat("zmax", 1, ValueRange::finite(), FileLoc());
  return std::make_unique<CylinderShape>(objectToWorld, reverseOrientation, radius, zMin, zMax,
                                         quadricPhiMax(params));
}

}  // namespace candela
