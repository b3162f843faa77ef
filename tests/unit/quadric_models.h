// Independent models of the quadrics for the tests: each shape's parameterisation p(u, v) in
// double precision, written from the lrt draft's definitions (§3.3–3.5), its inverse, and from
// these by finite differences the outward normal and the area element. The shapes' own code is
// checked against them.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "shapes/cone.h"
#include "shapes/cylinder.h"
#include "shapes/disk.h"
#include "shapes/hyperboloid.h"
#include "shapes/paraboloid.h"
#include "shapes/sphere.h"

namespace candela::test {

using D3 = std::array<double, 3>;

inline D3 sub(const D3& a, const D3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline D3 crossD(const D3& a, const D3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double dotD(const D3& a, const D3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline double lenD(const D3& a) { return std::sqrt(dotD(a, a)); }
inline D3 scaleD(const D3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
inline double azimuthD(double x, double y) {
  double phi = std::atan2(y, x);
  return phi < 0 ? phi + 2 * std::numbers::pi : phi;
}

struct QuadricModel {
  std::string name;
  std::function<std::unique_ptr<Quadric>(const Transform&, bool reverse)> make;
  std::function<D3(double u, double v)> P;   // object space
  std::function<Point2f(const D3& p)> uvOf;  // inverse of P on the surface
  bool flat = false;                         // the disk: outward is +z
  double size = 1;                           // a length of the shape's order
  double apexV = -1;  // v of an apex inside the parameter range (a through-axis hyperboloid)

  // Central differences of P.
  D3 dPdu(double u, double v, double h = 1e-6) const {
    return scaleD(sub(P(u + h, v), P(u - h, v)), 0.5 / h);
  }
  D3 dPdv(double u, double v, double h = 1e-6) const {
    return scaleD(sub(P(u, v + h), P(u, v - h)), 0.5 / h);
  }
  // The outward unit normal: away from the axis (+z for the disk).
  D3 outward(double u, double v) const {
    D3 n = crossD(dPdu(u, v), dPdv(u, v));
    D3 p = P(u, v);
    double side = flat ? n[2] : n[0] * p[0] + n[1] * p[1];
    return scaleD(n, (side < 0 ? -1 : 1) / lenD(n));
  }
  // The area of the parameter rectangle [u0, u1] x [v0, v1], by the midpoint rule.
  double area(double u0, double u1, double v0, double v1, int n = 64) const {
    double sum = 0, du = (u1 - u0) / n, dv = (v1 - v0) / n;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        double u = u0 + (i + 0.5) * du, v = v0 + (j + 0.5) * dv;
        sum += lenD(crossD(dPdu(u, v), dPdv(u, v)));
      }
    return sum * du * dv;
  }
};

inline double toRad(double deg) { return deg * std::numbers::pi / 180; }

inline QuadricModel sphereModel(double r, double zMin, double zMax, double phiMaxDeg) {
  double phiMax = toRad(phiMaxDeg), thetaMin = std::acos(zMin / r), thetaMax = std::acos(zMax / r);
  QuadricModel m;
  m.name = "sphere";
  m.size = r;
  m.make = [=](const Transform& t, bool rev) {
    return std::make_unique<SphereShape>(t, rev, Float(r), Float(zMin), Float(zMax),
                                         Float(phiMaxDeg));
  };
  m.P = [=](double u, double v) {
    double phi = u * phiMax, theta = thetaMin + v * (thetaMax - thetaMin);
    return D3{r * std::sin(theta) * std::cos(phi), r * std::sin(theta) * std::sin(phi),
              r * std::cos(theta)};
  };
  m.uvOf = [=](const D3& p) {
    double theta = std::atan2(std::hypot(p[0], p[1]), p[2]);
    return Point2f(Float(azimuthD(p[0], p[1]) / phiMax),
                   Float((theta - thetaMin) / (thetaMax - thetaMin)));
  };
  return m;
}

inline QuadricModel cylinderModel(double r, double zMin, double zMax, double phiMaxDeg) {
  double phiMax = toRad(phiMaxDeg);
  QuadricModel m;
  m.name = "cylinder";
  m.size = std::max(r, zMax - zMin);
  m.make = [=](const Transform& t, bool rev) {
    return std::make_unique<CylinderShape>(t, rev, Float(r), Float(zMin), Float(zMax),
                                           Float(phiMaxDeg));
  };
  m.P = [=](double u, double v) {
    double phi = u * phiMax;
    return D3{r * std::cos(phi), r * std::sin(phi), zMin + v * (zMax - zMin)};
  };
  m.uvOf = [=](const D3& p) {
    return Point2f(Float(azimuthD(p[0], p[1]) / phiMax), Float((p[2] - zMin) / (zMax - zMin)));
  };
  return m;
}

inline QuadricModel diskModel(double h, double r, double ri, double phiMaxDeg) {
  double phiMax = toRad(phiMaxDeg);
  QuadricModel m;
  m.name = "disk";
  m.flat = true;
  m.size = r;
  m.make = [=](const Transform& t, bool rev) {
    return std::make_unique<DiskShape>(t, rev, Float(h), Float(r), Float(ri), Float(phiMaxDeg));
  };
  m.P = [=](double u, double v) {
    double phi = u * phiMax, rho = r - v * (r - ri);
    return D3{rho * std::cos(phi), rho * std::sin(phi), h};
  };
  m.uvOf = [=](const D3& p) {
    return Point2f(Float(azimuthD(p[0], p[1]) / phiMax),
                   Float((r - std::hypot(p[0], p[1])) / (r - ri)));
  };
  return m;
}

inline QuadricModel coneModel(double h, double r, double phiMaxDeg) {
  double phiMax = toRad(phiMaxDeg);
  QuadricModel m;
  m.name = "cone";
  m.size = std::max(r, std::abs(h));
  m.make = [=](const Transform& t, bool rev) {
    return std::make_unique<ConeShape>(t, rev, Float(h), Float(r), Float(phiMaxDeg));
  };
  m.P = [=](double u, double v) {
    double phi = u * phiMax;
    return D3{r * (1 - v) * std::cos(phi), r * (1 - v) * std::sin(phi), v * h};
  };
  m.uvOf = [=](const D3& p) {
    return Point2f(Float(azimuthD(p[0], p[1]) / phiMax), Float(p[2] / h));
  };
  return m;
}

inline QuadricModel paraboloidModel(double r, double zMin, double zMax, double phiMaxDeg) {
  double phiMax = toRad(phiMaxDeg);
  QuadricModel m;
  m.name = "paraboloid";
  m.size = std::max(r, zMax);
  m.make = [=](const Transform& t, bool rev) {
    return std::make_unique<ParaboloidShape>(t, rev, Float(r), Float(zMin), Float(zMax),
                                             Float(phiMaxDeg));
  };
  m.P = [=](double u, double v) {
    double phi = u * phiMax, z = zMin + v * (zMax - zMin), rho = r * std::sqrt(z / zMax);
    return D3{rho * std::cos(phi), rho * std::sin(phi), z};
  };
  m.uvOf = [=](const D3& p) {
    return Point2f(Float(azimuthD(p[0], p[1]) / phiMax), Float((p[2] - zMin) / (zMax - zMin)));
  };
  return m;
}

// pbrt 2e/3e §3.5.3: rho^2 = d + k z^2 (a (x^2 + y^2) - c z^2 = 1, d = 1 / a, k = c / a) solved
// through p2 and q = 2 p2 - p1 by Cramer's rule; a line through the origin (no solution) sweeps
// the cone rho^2 = (rho2^2 / z2^2) z^2. v is linear in z; u is the angle from the segment's point
// at that height.
inline void hyperboloidModelFit(const D3& p1, const D3& p2, double* k, double* d) {
  D3 q = {2 * p2[0] - p1[0], 2 * p2[1] - p1[1], 2 * p2[2] - p1[2]};
  double s1 = q[0] * q[0] + q[1] * q[1], t1 = q[2] * q[2];
  double s2 = p2[0] * p2[0] + p2[1] * p2[1], t2 = p2[2] * p2[2];
  // Rows (s, -t) (a, c) = 1.
  double det = -s1 * t2 + s2 * t1;
  if (std::abs(det) <= 1e-12 * (s1 * t2 + s2 * t1)) {
    *k = s2 / t2;
    *d = 0;
    return;
  }
  double a = (-t2 + t1) / det, c = (s1 - s2) / det;
  *k = c / a;
  *d = 1 / a;
}

inline QuadricModel hyperboloidModel(const D3& p1, const D3& p2, double phiMaxDeg) {
  double phiMax = toRad(phiMaxDeg), k, d;
  hyperboloidModelFit(p1, p2, &k, &d);
  QuadricModel m;
  m.name = "hyperboloid";
  m.size = std::max({std::hypot(p1[0], p1[1]), std::hypot(p2[0], p2[1]), std::abs(p2[2] - p1[2])});
  m.make = [=](const Transform& t, bool rev) {
    return std::make_unique<HyperboloidShape>(
        t, rev, Point3f(Float(p1[0]), Float(p1[1]), Float(p1[2])),
        Point3f(Float(p2[0]), Float(p2[1]), Float(p2[2])), Float(phiMaxDeg));
  };
  m.P = [=](double u, double v) {
    double x = p1[0] + v * (p2[0] - p1[0]), y = p1[1] + v * (p2[1] - p1[1]);
    double z = p1[2] + v * (p2[2] - p1[2]);
    double theta = std::atan2(y, x) + u * phiMax, rho = std::sqrt(std::max(0.0, d + k * z * z));
    return D3{rho * std::cos(theta), rho * std::sin(theta), z};
  };
  m.uvOf = [=](const D3& p) {
    double v = (p[2] - p1[2]) / (p2[2] - p1[2]);
    double x = p1[0] + v * (p2[0] - p1[0]), y = p1[1] + v * (p2[1] - p1[1]);
    return Point2f(Float(azimuthD(x * p[0] + y * p[1], x * p[1] - y * p[0]) / phiMax), Float(v));
  };
  return m;
}

// Partial shapes of every kind, including the singular ones (apex, centre, pole) and the
// orientations whose parameterisation points inward (negative cone height, hyperboloid with p2
// below p1), and hyperboloid fits of each kind (one sheet, ellipsoid, cone through the origin). No
// full sphere: its solid-angle sampling covers the visible cone, not the area.
inline std::vector<QuadricModel> allModels() {
  // A segment through the origin: the cone it sweeps, apex at v = 2/3.
  QuadricModel throughAxis = hyperboloidModel({0.9, 0.3, -0.6}, {-0.45, -0.15, 0.3}, 360);
  throughAxis.apexV = 2.0 / 3;
  return {sphereModel(1.2, -0.7, 0.9, 260),
          sphereModel(0.9, -0.9, 0.4, 360),
          cylinderModel(1.5, -0.5, 1, 270),
          cylinderModel(0.7, 0, 2, 360),
          diskModel(0.3, 1.2, 0.4, 300),
          diskModel(-0.2, 1, 0, 360),
          coneModel(1.7, 1.3, 250),
          coneModel(-1, 0.8, 360),
          paraboloidModel(1.1, 0.2, 1.4, 290),
          paraboloidModel(1, 0, 1, 360),
          hyperboloidModel({1, 0.3, -0.8}, {-0.2, 1.1, 0.9}, 280),
          hyperboloidModel({0.4, 0.9, 0.7}, {1, 0, -0.6}, 360),
          hyperboloidModel({1.2, 0.2, -0.2}, {0.9, 0.3, 0.3}, 310),  // part of an ellipsoid
          throughAxis};
}

// The world point p of shape (made with objectToWorld t) in object space, in double.
inline D3 toObject(const Transform& t, const Point3f& p) {
  const auto& mi = t.inverseMatrix().m;
  D3 q;
  for (int i = 0; i < 3; ++i)
    q[i] = double(mi[i][0]) * p.x + double(mi[i][1]) * p.y + double(mi[i][2]) * p.z + mi[i][3];
  return q;
}

// Upper-tail probability of the chi-square distribution with dof degrees of freedom (Wilson and
// Hilferty's normal approximation, good to a few per cent of p for dof >= 10).
inline double chiSquarePValue(double chi2, int dof) {
  double k = dof, z = (std::cbrt(chi2 / k) - (1 - 2 / (9 * k))) / std::sqrt(2 / (9 * k));
  return 0.5 * std::erfc(z / std::sqrt(2.0));
}

}  // namespace candela::test
