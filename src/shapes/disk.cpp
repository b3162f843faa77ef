#include "shapes/disk.h"

#include "core/sampling.h"

namespace candela {

DiskShape::DiskShape(const Transform& objectToWorld, bool reverseOrientation, Float height,
                     Float radius, Float innerRadius, Float phiMaxDeg)
    : Quadric(objectToWorld, reverseOrientation),
      height_(height),
      radius_(radius),
      innerRadius_(clamp(innerRadius, 0, radius)),
      phiMax_(phiMaxRadians(phiMaxDeg)) {
  // phiMax (r^2 - ri^2) / 2 (lrt draft §3.4.4 for ri = 0).
  objectArea_ = 0.5 * phiMax_ * (radius_ - innerRadius_) * (radius_ + innerRadius_);
  const auto& m = objectToWorld.matrix().m;
  Vector3f ex(m[0][0], m[1][0], m[2][0]), ey(m[0][1], m[1][1], m[2][1]);
  worldAreaScale_ = cross(ex, ey).length();
  setBoundingBall();
}

Bounds3f DiskShape::objectBound() const {
  Float r = Float(radius_), h = Float(height_);
  return Bounds3f(Point3f(-r, -r, h), Point3f(r, r, h));
}

Float DiskShape::area() const { return Float(objectArea_ * worldAreaScale_); }

void DiskShape::lineCoefficients(const double o[3], const double d[3], double* a, double* b,
                                 double* c) const {
  // The plane z = h: linear in t. A ray parallel to it (b = 0) misses; the draft's |d.z| < 1e-7
  // cut-off (lrt draft §3.4.2) is replaced by the root's error test.
  *a = 0;
  *b = d[2];
  *c = o[2] - height_;
}

double DiskShape::implicit(const double p[3], double* fErr, double grad[3]) const {
  *fErr = std::numeric_limits<double>::epsilon() * (std::abs(p[2]) + std::abs(height_));
  grad[0] = grad[1] = 0;
  grad[2] = 1;
  return p[2] - height_;
}

bool DiskShape::clip(double p[3]) const {
  p[2] = height_;  // exactly on the plane
  double rho2 = p[0] * p[0] + p[1] * p[1];
  if (rho2 > radius_ * radius_ || rho2 < innerRadius_ * innerRadius_) return false;
  return phiMax_ >= 2 * std::numbers::pi || azimuth(p[0], p[1]) <= phiMax_;
}

Quadric::LocalGeometry DiskShape::geometryAt(const double p[3]) const {
  double rho = std::sqrt(p[0] * p[0] + p[1] * p[1]);
  double phi = azimuth(p[0], p[1]);
  LocalGeometry g;
  g.uv = Point2f(Float(phi / phiMax_), Float((radius_ - rho) / (radius_ - innerRadius_)));
  // dp/dv = (x, y, 0) (ri - r) / rho, the draft's (-x, -y, 0) / (1 - v) for ri = 0, which is 0/0
  // at the centre; there and for dp/du = phiMax (-y, x, 0), which vanishes, the tangents are
  // taken a little off the centre (seed notes §23: disk centre).
  double rhoG = std::max(rho, kAxisNudge * radius_);
  double cosPhi = std::cos(phi), sinPhi = std::sin(phi);
  g.dpdu = Vector3f(Float(-phiMax_ * rhoG * sinPhi), Float(phiMax_ * rhoG * cosPhi), 0);
  g.dpdv = Vector3f(Float(cosPhi * (innerRadius_ - radius_)),
                    Float(sinPhi * (innerRadius_ - radius_)), 0);
  // The plane's normal does not turn: dn/du = dn/dv = 0 (all second derivatives lie in it).
  return g;
}

void DiskShape::sampleObject(const Point2f& u, double p[3]) const {
  p[2] = height_;
  if (innerRadius_ == 0 && phiMax_ >= 2 * std::numbers::pi) {
    Point2f d = sampleUniformDiskConcentric(u);
    p[0] = radius_ * d.x;
    p[1] = radius_ * d.y;
    return;
  }
  // rho^2 uniform in [ri^2, r^2] and phi uniform in [0, phiMax]: uniform by area on the sector.
  double r2 = (1 - double(u.x)) * innerRadius_ * innerRadius_ + double(u.x) * radius_ * radius_;
  double rho = std::sqrt(r2), phi = u.y * phiMax_;
  p[0] = rho * std::cos(phi);
  p[1] = rho * std::sin(phi);
}

std::unique_ptr<Shape> createDiskShape(const Transform& objectToWorld, bool reverseOrientation,
                                       const ParamSet& params) {
  Float height = params.getOneFloat("height", 0, ValueRange::finite(), FileLoc());
  Float radius = params.getOneFloat("radius", 1, ValueRange::positive(), FileLoc());
  Float inner = params.getOneFloat("innerradius", 0, ValueRange::nonNegative(), FileLoc());
  // The upper limit depends on "radius", so it is no ValueRange of its own.
  if (inner >= radius)
    throw SceneError(params.locationOf("innerradius", FileLoc()),
                     "\"innerradius\" must be less than \"radius\" = " + formatNumber(radius) +
                         " (got " + formatNumber(inner) + ")");
  return std::make_unique<DiskShape>(objectToWorld, reverseOrientation, height, radius, inner,
                                     quadricPhiMax(params));
}

}  // namespace candela
