#include "shapes/hyperboloid.h"

namespace candela {

HyperboloidShape::HyperboloidShape(const Transform& objectToWorld, bool reverseOrientation,
                                   const Point3f& p1, const Point3f& p2, Float phiMaxDeg)
    : Quadric(objectToWorld, reverseOrientation), phiMax_(phiMaxRadians(phiMaxDeg)) {
  for (int i = 0; i < 3; ++i) {
    p1_[i] = p1[i];
    delta_[i] = double(p2[i]) - p1[i];
  }
  double dz = delta_[2];
  invDz_ = dz != 0 ? 1 / dz : 0;
  alpha_ = delta_[0] * delta_[0] + delta_[1] * delta_[1];
  beta_ = 2 * (p1_[0] * delta_[0] + p1_[1] * delta_[1]);
  gamma_ = p1_[0] * p1_[0] + p1_[1] * p1_[1];
  rMax_ = std::max(std::hypot(p1_[0], p1_[1]), std::hypot(double(p2.x), double(p2.y)));
  zMin_ = std::min(p1.z, p2.z);
  zMax_ = std::max(p1.z, p2.z);
  // |dp/du x dp/dv|^2 / phiMax^2 = dz^2 R(v) + R'(v)^2 / 4 =: Q(v), a quadratic; written as
  // qa (v + qb)^2 + qd with qd = dz^2 (x1 dy - y1 dx)^2 / alpha (Lagrange's identity), which
  // needs no cancelling subtraction.
  qa_ = alpha_ * (dz * dz + alpha_);
  if (qa_ > 0) {
    qb_ = beta_ / (2 * alpha_);
    double cr = p1_[0] * delta_[1] - p1_[1] * delta_[0];
    qd_ = dz * dz * cr * cr / alpha_;
  } else {
    qb_ = 0;
    qd_ = dz * dz * gamma_;  // a cylinder: Q is constant
  }
  // dp/du x dp/dv has the radial component phiMax rho dz.
  crossPointsInward_ = dz < 0;
  objectArea_ = dz != 0 ? phiMax_ * stripIntegral(1) : 0;
}

double HyperboloidShape::stripIntegral(double v) const {
  if (qa_ == 0) return std::sqrt(qd_) * v;
  // The antiderivative of sqrt(qa w^2 + qd): (w sqrt(qa w^2 + qd) + qd / sqrt(qa)
  // asinh(w sqrt(qa / qd))) / 2; the second term vanishes with qd (the segment meets the axis).
  auto G = [&](double w) {
    double s = std::sqrt(qa_ * w * w + qd_);
    double g = w * s;
    if (qd_ > 0) g += qd_ / std::sqrt(qa_) * std::asinh(w * std::sqrt(qa_ / qd_));
    return 0.5 * g;
  };
  return G(v + qb_) - G(qb_);
}

Bounds3f HyperboloidShape::objectBound() const {
  // The distance from the axis is convex along the segment: largest at an end.
  Float r = Float(rMax_);
  return Bounds3f(Point3f(-r, -r, Float(zMin_)), Point3f(r, r, Float(zMax_)));
}

void HyperboloidShape::lineCoefficients(const double o[3], const double d[3], double* a, double* b,
                                        double* c) const {
  // x^2 + y^2 - R(v) with v = v0 + t v1 along the line.
  double v0 = (o[2] - p1_[2]) * invDz_, v1 = d[2] * invDz_;
  *a = d[0] * d[0] + d[1] * d[1] - alpha_ * v1 * v1;
  *b = 2 * (d[0] * o[0] + d[1] * o[1]) - (2 * alpha_ * v0 + beta_) * v1;
  *c = o[0] * o[0] + o[1] * o[1] - ((alpha_ * v0 + beta_) * v0 + gamma_);
}

double HyperboloidShape::implicit(const double p[3], double* fErr, double grad[3]) const {
  double v = (p[2] - p1_[2]) * invDz_;
  double x2 = p[0] * p[0] + p[1] * p[1];
  double R = (alpha_ * v + beta_) * v + gamma_;
  *fErr = 10 * std::numeric_limits<double>::epsilon() *
          (x2 + alpha_ * v * v + std::abs(beta_ * v) + gamma_);
  grad[0] = 2 * p[0];
  grad[1] = 2 * p[1];
  grad[2] = -(2 * alpha_ * v + beta_) * invDz_;
  return x2 - R;
}

double HyperboloidShape::sweepAngle(const double p[3], double v) const {
  double rx = p1_[0] + v * delta_[0], ry = p1_[1] + v * delta_[1];
  // The angle from (rx, ry) to (x, y); 0 where the segment meets the axis (an apex).
  return azimuth(rx * p[0] + ry * p[1], rx * p[1] - ry * p[0]);
}

bool HyperboloidShape::clip(double p[3]) const {
  double v = (p[2] - p1_[2]) * invDz_;
  if (!(v >= 0 && v <= 1)) return false;
  return phiMax_ >= 2 * std::numbers::pi || sweepAngle(p, v) <= phiMax_;
}

Quadric::LocalGeometry HyperboloidShape::geometryAt(const double p[3]) const {
  double v = (p[2] - p1_[2]) * invDz_;
  double phi = sweepAngle(p, v);
  double cosPhi = std::cos(phi), sinPhi = std::sin(phi);
  LocalGeometry g;
  g.uv = Point2f(Float(phi / phiMax_), Float(v));
  // dp/dv is the segment's direction turned by phi; dp/du = phiMax (-y, x, 0), taken a little
  // off the axis where the segment meets it (an apex, seed notes §23).
  double dx = delta_[0] * cosPhi - delta_[1] * sinPhi, dy = delta_[0] * sinPhi + delta_[1] * cosPhi;
  double xg = p[0], yg = p[1], rho = std::hypot(xg, yg), rhoMin = kAxisNudge * rMax_;
  if (rho < rhoMin) {
    // Along the point's own direction, or (exactly on the axis) the side v grows to.
    double ux = rho > 0 ? xg / rho : dx, uy = rho > 0 ? yg / rho : dy;
    double len = std::hypot(ux, uy);
    if (len > 0) {
      xg = rhoMin * ux / len;
      yg = rhoMin * uy / len;
    } else {
      xg = rhoMin;
      yg = 0;
    }
  }
  g.dpdu = Vector3f(Float(-phiMax_ * yg), Float(phiMax_ * xg), 0);
  g.dpdv = Vector3f(Float(dx), Float(dy), Float(delta_[2]));
  g.d2Pduu = Vector3f(Float(-phiMax_ * phiMax_ * xg), Float(-phiMax_ * phiMax_ * yg), 0);
  g.d2Pduv = Vector3f(Float(-phiMax_ * dy), Float(phiMax_ * dx), 0);
  return g;  // d2p/dv2 = 0: the rulings are straight
}

void HyperboloidShape::sampleObject(const Point2f& u, double p[3]) const {
  // v with density sqrt(Q(v)) / stripIntegral(1): solve stripIntegral(v) = u stripIntegral(1).
  // The function is increasing with derivative sqrt(Q(v)); Newton steps that would leave the
  // bracket, or a zero derivative (an apex), fall back to bisection.
  double total = stripIntegral(1), target = double(u.x) * total;
  double v = u.x, lo = 0, hi = 1;
  if (qa_ > 0 && total > 0) {
    for (int i = 0; i < 60; ++i) {
      double h = stripIntegral(v) - target;
      if (h > 0)
        hi = v;
      else
        lo = v;
      double w = v + qb_, deriv = std::sqrt(qa_ * w * w + qd_);
      double next = deriv > 0 ? v - h / deriv : 0.5 * (lo + hi);
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      if (std::abs(next - v) <= 1e-15) break;
      v = next;
    }
  }
  double phi = u.y * phiMax_, cosPhi = std::cos(phi), sinPhi = std::sin(phi);
  double rx = p1_[0] + v * delta_[0], ry = p1_[1] + v * delta_[1];
  p[0] = rx * cosPhi - ry * sinPhi;
  p[1] = rx * sinPhi + ry * cosPhi;
  p[2] = p1_[2] + v * delta_[2];
}

std::unique_ptr<Shape> createHyperboloidShape(const Transform& objectToWorld,
                                              bool reverseOrientation, const ParamSet& params) {
  Point3f p1 = params.getOnePoint3f("p1", Point3f(0, 0, 0));
  Point3f p2 = params.getOnePoint3f("p2", Point3f(1, 1, 1));
  for (const char* name : {"p1", "p2"}) {
    Point3f p = std::string(name) == "p1" ? p1 : p2;
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw SceneError(params.locationOf(name, FileLoc()),
                       std::string("hyperboloid \"") + name + "\" must be finite");
  }
  if (p1.z == p2.z)
    throw SceneError(params.locationOf("p2", FileLoc()),
                     "hyperboloid \"p1\" and \"p2\" must differ in z (use a disk with an "
                     "\"innerradius\" for a flat ring)");
  return std::make_unique<HyperboloidShape>(objectToWorld, reverseOrientation, p1, p2,
                                            quadricPhiMax(params));
}

}  // namespace candela
