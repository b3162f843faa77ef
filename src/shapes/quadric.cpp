#include "shapes/quadric.h"

#include <numbers>
#include <string>

#include "core/error.h"

namespace candela {

namespace {

// gamma(n) for double's unit roundoff (pbrt 3e §3.9.1).
constexpr double doubleGamma(int n) {
  constexpr double u = std::numeric_limits<double>::epsilon() / 2;
  return n * u / (1 - n * u);
}

bool allFinite(const double v[3]) {
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

double dot3(const double a[3], const double b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// Whether t is affine and its linear part keeps spheres spheres; *scale is the cube root of |det|
// (exact for a similarity).
bool similarityScale(const Transform& t, double* scale) {
  const auto& m = t.matrix().m;
  double c[3][3];
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) c[j][i] = m[i][j];
  double det = c[0][0] * (c[1][1] * c[2][2] - c[1][2] * c[2][1]) -
               c[0][1] * (c[1][0] * c[2][2] - c[1][2] * c[2][0]) +
               c[0][2] * (c[1][0] * c[2][1] - c[1][1] * c[2][0]);
  *scale = std::cbrt(std::abs(det));
  if (m[3][0] != 0 || m[3][1] != 0 || m[3][2] != 0 || m[3][3] != 1) return false;
  double s2 = *scale * *scale, tol = 1e-4 * s2;
  for (int i = 0; i < 3; ++i) {
    if (std::abs(dot3(c[i], c[i]) - s2) > tol) return false;
    if (std::abs(dot3(c[i], c[(i + 1) % 3])) > tol) return false;
  }
  return true;
}

}  // namespace

Quadric::Quadric(const Transform& objectToWorld, bool reverseOrientation)
    : objectToWorld_(objectToWorld),
      reverseOrientation_(reverseOrientation),
      transformSwapsHandedness_(objectToWorld.swapsHandedness()) {
  // The affine rows in double and their inverse by cofactors, also in double: the world-object
  // round trip is then exact to double precision.
  const auto& m = objectToWorld_.matrix().m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) o2w_[i][j] = m[i][j];
  const double(&A)[3][4] = o2w_;
  double det = A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) -
               A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
               A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
  invertible_ = det != 0 && std::isfinite(det);
  double inv = invertible_ ? 1 / det : 0;
  for (int i = 0; i < 3; ++i) {
    int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
    for (int j = 0; j < 3; ++j) {
      int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      w2o_[i][j] = (A[j1][i1] * A[j2][i2] - A[j1][i2] * A[j2][i1]) * inv;
    }
  }
  for (int i = 0; i < 3; ++i)
    w2o_[i][3] = -(w2o_[i][0] * A[0][3] + w2o_[i][1] * A[1][3] + w2o_[i][2] * A[2][3]);
  isSimilarity_ = similarityScale(objectToWorld_, &worldScale_);
}

double Quadric::azimuth(double x, double y) {
  // On the axis phi is undefined; 0 whatever the zeros' signs (atan2(-0, -0) is -pi), so that a
  // pole or apex hit is inside every sweep.
  if (x == 0 && y == 0) return 0;
  double phi = std::atan2(y, x);
  return phi < 0 ? phi + 2 * std::numbers::pi : phi;
}

double Quadric::phiMaxRadians(Float phiMaxDeg) {
  return phiMaxDeg >= 360 ? 2 * std::numbers::pi
                          : double(clamp(phiMaxDeg, 0, 360)) * (std::numbers::pi / 180);
}

double Quadric::objectExtent() const {
  Bounds3f b = objectBound();
  return std::max(maxComponent(abs(Vector3f(b.pMin))), maxComponent(abs(Vector3f(b.pMax))));
}

Bounds3f Quadric::worldBound() const {
  // Corners padded by their transformation error: Embree culls user geometry by this box
  // (pbrt 3e §3.9.4).
  Bounds3f ob = objectBound(), wb;
  for (int c = 0; c < 8; ++c) {
    Vector3f err;
    Point3f p = objectToWorld_.apply(ob.corner(c), &err);
    err = err * 2 + abs(Vector3f(p)) * gamma(1);
    wb = unionOf(wb, p - err);
    wb = unionOf(wb, p + err);
  }
  return wb;
}

void Quadric::setBoundingBall() {
  Bounds3f b = objectBound();
  double centre[3], half2 = 0;
  for (int i = 0; i < 3; ++i) {
    centre[i] = 0.5 * (double(b.pMin[i]) + double(b.pMax[i]));
    double h = 0.5 * (double(b.pMax[i]) - double(b.pMin[i]));
    half2 += h * h;
  }
  setBoundingBall(centre, std::sqrt(half2));
}

void Quadric::setBoundingBall(const double centre[3], double radius) {
  // The ball's image holds the shape's: its radius grows by the transform's largest stretch,
  // exact for similarities, else bounded by the Frobenius norm of the linear part.
  double stretch = worldScale_;
  if (!isSimilarity_) {
    stretch = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) stretch += o2w_[i][j] * o2w_[i][j];
    stretch = std::sqrt(stretch);
  }
  double c[3];
  for (int i = 0; i < 3; ++i)
    c[i] = o2w_[i][0] * centre[0] + o2w_[i][1] * centre[1] + o2w_[i][2] * centre[2] + o2w_[i][3];
  double r = radius * stretch * (1 + 1e-6);
  if (!allFinite(c) || !std::isfinite(r) || !(r < 1e30)) return;  // no ball: nothing rejected
  worldBallCentre_ = Point3f(Float(c[0]), Float(c[1]), Float(c[2]));
  // The centre's rounding to float, and headroom.
  worldBallRadius_ = Float(r + 1e-6 * (std::abs(c[0]) + std::abs(c[1]) + std::abs(c[2])));
  hasWorldBall_ = true;
}

bool Quadric::passesBall(const Ray& r) const {
  // In float, with a margin of 1e-5 of the distances involved: the few rounding errors here are
  // below 1e-6 of them. Whatever overflows, or is NaN, is left to findHit's own tests.
  Vector3f v = r.o - worldBallCentre_;
  Float dd = r.d.lengthSquared();
  Float vNorm = std::abs(v.x) + std::abs(v.y) + std::abs(v.z);
  Float reach = worldBallRadius_ * (1 + Float(1e-4)) + Float(1e-5) * vNorm;
  Float c2 = cross(v, r.d).lengthSquared(), reach2dd = reach * reach * dd;
  if (!std::isfinite(c2) || !std::isfinite(reach2dd) || !(dd > 0)) return false;
  if (c2 > reach2dd) return true;  // the line passes the ball by
  // The chord along the line: outside [0, tMax] (with the same margin) it is missed.
  Float tNear = -dot(v, r.d) / dd;
  Float half = std::sqrt(reach2dd - c2) / dd;
  Float slackT = Float(1e-5) * (std::abs(tNear) + half);
  return tNear + half + slackT < 0 || tNear - half - slackT > r.tMax;
}

bool Quadric::findHit(const Ray& r, Hit* hit) const {
  // Zero-area shapes (zmin = zmax, ...) have no tangent plane to report: they are never hit.
  if (!invertible_ || !(objectArea_ > 0) || std::isnan(r.tMax)) return false;
  // Most rays a callback is asked about pass the shape by: its bounding ball decides them first.
  if (hasWorldBall_ && passesBall(r)) return false;
  // To object space in double, with the bound of that arithmetic's own rounding (the float ray is
  // exact input).
  double o[3], d[3];
  for (int i = 0; i < 3; ++i) {
    const double* m = w2o_[i];
    o[i] = m[0] * r.o.x + m[1] * r.o.y + m[2] * r.o.z + m[3];
    d[i] = m[0] * r.d.x + m[1] * r.d.y + m[2] * r.d.z;
  }
  if (!allFinite(o) || !allFinite(d)) return false;  // NaN and infinite rays miss
  double dd = dot3(d, d);
  if (!(dd > 0)) return false;
  double oErr[3], dErr[3];
  for (int i = 0; i < 3; ++i) {
    const double* m = w2o_[i];
    oErr[i] = doubleGamma(4) * (std::abs(m[0] * r.o.x) + std::abs(m[1] * r.o.y) +
                                std::abs(m[2] * r.o.z) + std::abs(m[3]));
    dErr[i] =
        doubleGamma(4) * (std::abs(m[0] * r.d.x) + std::abs(m[1] * r.d.y) + std::abs(m[2] * r.d.z));
  }

  // Move the origin along the line to the point nearest the object's origin: the coefficients
  // then stay well scaled for rays from far away (the idea of pbrt 4e §6.8.2's discriminant).
  // The move's own rounding is added to the origin's error.
  double t0 = -dot3(o, d) / dd, os[3], osErr[3];
  for (int i = 0; i < 3; ++i) {
    os[i] = o[i] + t0 * d[i];
    osErr[i] =
        oErr[i] + std::abs(t0) * dErr[i] + doubleGamma(3) * (std::abs(o[i]) + std::abs(t0 * d[i]));
  }
  double a, b, c;
  lineCoefficients(os, d, &a, &b, &c);
  double roots[2];
  int nRoots;
  if (a == 0) {  // a plane, or a line parallel to a ruling
    if (b == 0) return false;
    roots[0] = -c / b;
    nRoots = 1;
  } else {
    // The stable quadratic (lrt draft §3.2.2).
    double discrim = b * b - 4 * a * c;
    if (!(discrim >= 0)) return false;
    double root = std::sqrt(discrim);
    double q = (b < 0) ? -0.5 * (b - root) : -0.5 * (b + root);
    if (q == 0) {
      roots[0] = 0;
      nRoots = 1;
    } else {
      roots[0] = q / a;
      roots[1] = c / q;
      if (roots[0] > roots[1]) std::swap(roots[0], roots[1]);
      nRoots = 2;
    }
  }

  for (int k = 0; k < nRoots; ++k) {
    double tShift = roots[k], t = t0 + tShift;
    Float tf = Float(t);
    if (!(tf < r.tMax)) return false;  // roots ascend
    double p[3] = {os[0] + tShift * d[0], os[1] + tShift * d[1], os[2] + tShift * d[2]};
    // A root no farther from the origin than its own uncertainty is the surface the ray leaves.
    // To first order the errors of origin and direction move the root by
    // -grad F . (dos + t' dd) / (grad F . d): pbrt 3e's conservative t > 0 test (§3.9.6) for our
    // double arithmetic, for any implicit surface.
    double fErr, grad[3];
    implicit(p, &fErr, grad);
    double sens = 0, gLen2 = dot3(grad, grad);
    if (gLen2 > 0) {
      for (int i = 0; i < 3; ++i)
        sens += std::abs(grad[i]) * (osErr[i] + std::abs(tShift) * dErr[i]);
      if (!(t * std::abs(dot3(grad, d)) > 2 * sens)) continue;
    } else {
      // A singular point (an apex) hit exactly: F is flat there, so ask only that the hit be
      // farther along the ray than the origin's uncertainty.
      for (int i = 0; i < 3; ++i) sens += osErr[i] + std::abs(tShift) * dErr[i];
      if (!(t * std::sqrt(dd) > 2 * sens)) continue;
    }
    if (!(tf > 0)) continue;
    // Clipped by the shape's ranges: then the far root may still be on it (lrt draft §3.2.2).
    if (!clip(p)) continue;
    hit->t = tf;
    std::copy(p, p + 3, hit->p);
    return true;
  }
  return false;
}

Point3f Quadric::toWorld(const double p[3], Vector3f* pError) const {
  // The point's distance from the exact surface, |F| / |grad F| to first order plus F's rounding;
  // tiny in double, but it makes the bound hold for every quadric without reprojection. Where the
  // gradient vanishes (an apex) the point is exact to double precision: use the extent's rounding.
  double fErr, grad[3];
  double f = implicit(p, &fErr, grad);
  double gLen = std::sqrt(dot3(grad, grad));
  double extent = objectExtent();
  double floor = doubleGamma(8) * (extent + std::abs(p[0]) + std::abs(p[1]) + std::abs(p[2]));
  double dist = gLen > 0 ? (std::abs(f) + fErr) / gLen : 0;
  if (!(dist <= 1e-6 * extent)) dist = 1e-6 * extent;  // only near a singular point
  dist = 2 * dist + floor;
  // The transform in double is within doubleGamma(4) of the exact image of p; rounding to float
  // adds half an ulp, which gamma(2) |p| covers.
  Point3f pw;
  for (int i = 0; i < 3; ++i) {
    const double* m = o2w_[i];
    double v = m[0] * p[0] + m[1] * p[1] + m[2] * p[2] + m[3];
    double err = doubleGamma(4) * (std::abs(m[0] * p[0]) + std::abs(m[1] * p[1]) +
                                   std::abs(m[2] * p[2]) + std::abs(m[3])) +
                 (std::abs(m[0]) + std::abs(m[1]) + std::abs(m[2])) * dist;
    pw[i] = Float(v);
    (*pError)[i] = gamma(2) * std::abs(pw[i]) + nextFloatUp(Float(err));
  }
  return pw;
}

void Quadric::toObjectVector(const Vector3f& w, double v[3]) const {
  for (int i = 0; i < 3; ++i) v[i] = w2o_[i][0] * w.x + w2o_[i][1] * w.y + w2o_[i][2] * w.z;
}

void Quadric::weingarten(const LocalGeometry& g, Normal3f* dndu, Normal3f* dndv) {
  // Coefficients of the first (E, F, G) and second (e, f, g) fundamental forms, then dn/du, dn/dv
  // as combinations of dp/du, dp/dv (lrt draft §3.2.4).
  double E = dot(g.dpdu, g.dpdu), F = dot(g.dpdu, g.dpdv), G = dot(g.dpdv, g.dpdv);
  Vector3f c = cross(g.dpdu, g.dpdv);
  double egf2 = E * G - F * F;
  if (!(c.lengthSquared() > 0) || !(egf2 > 0)) {
    *dndu = *dndv = Normal3f();
    return;
  }
  Vector3f N = normalize(c);
  double e = dot(N, g.d2Pduu), f = dot(N, g.d2Pduv), gg = dot(N, g.d2Pdvv);
  double inv = 1 / egf2;
  *dndu = Normal3f(g.dpdu * Float((f * F - e * G) * inv) + g.dpdv * Float((e * F - f * E) * inv));
  *dndv = Normal3f(g.dpdu * Float((gg * F - f * G) * inv) + g.dpdv * Float((f * F - gg * E) * inv));
}

bool Quadric::intersectP(const Ray& ray) const {
  Hit hit;
  return findHit(ray, &hit);
}

bool Quadric::intersect(const Ray& ray, Float* tHit, SurfaceInteraction* isect) const {
  Hit hit;
  if (!findHit(ray, &hit)) return false;
  *tHit = hit.t;
  if (!isect) return true;

  LocalGeometry g = geometryAt(hit.p);
  Normal3f dndu, dndv;
  weingarten(g, &dndu, &dndv);
  // dn/du, dn/dv are those of the outward normal: the Weingarten equations give them for
  // normalize(dp/du x dp/dv).
  Vector3f c = normalize(cross(g.dpdu, g.dpdv));
  if (crossPointsInward_) {
    c = -c;
    dndu = -dndu;
    dndv = -dndv;
  }
  // To world space as derivatives of the unit normal M^-T n / |M^-T n|: the tangential part of
  // M^-T dn, divided by |M^-T n|. (Transforming dn as a normal alone, as pbrt 3e does, scales it
  // by 1/s under a uniform scale s.)
  Normal3f nT = objectToWorld_(Normal3f(c.x, c.y, c.z));
  Float nLen = nT.length();
  auto worldDn = [&](const Normal3f& dn) {
    if (!(nLen > 0)) return Normal3f();
    Normal3f nw = nT / nLen, v = objectToWorld_(dn);
    return (v - nw * dot(nw, v)) / nLen;
  };
  Vector3f pErr;
  Point3f pWorld = toWorld(hit.p, &pErr);
  Vector3f wo = -ray.d;
  Float woLen = wo.length();
  if (woLen > 0) wo = wo / woLen;
  // The world cross product flips under a mirroring transform; the xor restores the outward side,
  // which ReverseOrientation then turns around (lrt draft §2.8, pbrt 3e §2.10.1).
  bool flip = (reverseOrientation_ != transformSwapsHandedness_) != crossPointsInward_;
  *isect = SurfaceInteraction(pWorld, pErr, g.uv, wo, objectToWorld_(g.dpdu),
                              objectToWorld_(g.dpdv), worldDn(dndu), worldDn(dndv), ray.time, flip);
  return true;
}

Float Quadric::area() const { return Float(objectArea_ * worldScale_ * worldScale_); }

Interaction Quadric::sample(const Point2f& u, Float* pdf) const {
  double p[3];
  sampleObject(u, p);
  LocalGeometry g = geometryAt(p);
  Vector3f c = cross(g.dpdu, g.dpdv);
  if (crossPointsInward_) c = -c;
  // Transformed as a normal, the outward normal stays outward under mirrors; only
  // ReverseOrientation turns it.
  Normal3f n = objectToWorld_(Normal3f(c.x, c.y, c.z));
  Float a = area();
  if (!(n.lengthSquared() > 0) || !(a > 0)) {
    *pdf = 0;
    return Interaction();
  }
  n = normalize(n);
  if (reverseOrientation_) n = -n;
  Vector3f pErr;
  Point3f pw = toWorld(p, &pErr);
  *pdf = 1 / a;
  return Interaction(pw, n, pErr, Vector3f(), 0);
}

Float quadricPhiMax(const ParamSet& params, Float def) {
  return params.find("phimax") ? params.getOneFloat("phimax", def)
                               : params.getOneFloat("thetamax", def);
}

}  // namespace candela
