#include "shapes/sphere.h"

#include "core/sampling.h"

namespace candela {

namespace {

// Does the linear part of m map spheres to spheres (columns orthogonal, of equal length)? Also
// returns the world length per object length (the cube root of |det|, exact for similarities).
bool isSimilarityTransform(const Transform& t, Float* scale) {
  const auto& m = t.matrix().m;
  Vector3f c[3];
  for (int j = 0; j < 3; ++j) c[j] = Vector3f(m[0][j], m[1][j], m[2][j]);
  double det = double(dot(c[0], cross(c[1], c[2])));
  *scale = Float(std::cbrt(std::abs(det)));
  if (m[3][0] != 0 || m[3][1] != 0 || m[3][2] != 0 || m[3][3] != 1) return false;
  Float s2 = *scale * *scale, tol = 1e-4f * s2;
  for (int i = 0; i < 3; ++i) {
    if (std::abs(dot(c[i], c[i]) - s2) > tol) return false;
    if (std::abs(dot(c[i], c[(i + 1) % 3])) > tol) return false;
  }
  return true;
}

}  // namespace

SphereShape::SphereShape(const Transform& objectToWorld, bool reverseOrientation, Float radius,
                         Float zMin, Float zMax, Float phiMaxDeg)
    : objectToWorld_(objectToWorld),
      worldToObject_(inverse(objectToWorld)),
      reverseOrientation_(reverseOrientation),
      transformSwapsHandedness_(objectToWorld.swapsHandedness()),
      radius_(radius),
      zMin_(clamp(std::min(zMin, zMax), -radius, radius)),
      zMax_(clamp(std::max(zMin, zMax), -radius, radius)),
      thetaZMin_(std::acos(clamp(zMin_ / radius, -1, 1))),
      thetaZMax_(std::acos(clamp(zMax_ / radius, -1, 1))),
      phiMax_(phiMaxDeg >= 360 ? 2 * kPi : radians(clamp(phiMaxDeg, 0, 360))),
      isFullSphere_(zMin_ <= -radius && zMax_ >= radius && phiMaxDeg >= 360) {
  // The affine rows in double, and their inverse computed in double (cofactors), so that the
  // world-object round trip is exact to double precision.
  const auto& m = objectToWorld_.matrix().m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) o2w_[i][j] = m[i][j];
  double(&A)[3][4] = o2w_;
  double det = A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) -
               A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
               A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
  invertible_ = det != 0 && std::isfinite(det);
  double inv = invertible_ ? 1 / det : 0;
  for (int i = 0; i < 3; ++i) {
    int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
    for (int j = 0; j < 3; ++j) {
      int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      // (A^-1)_ij = cofactor_ji / det
      w2o_[i][j] = (A[j1][i1] * A[j2][i2] - A[j1][i2] * A[j2][i1]) * inv;
    }
  }
  for (int i = 0; i < 3; ++i)
    w2o_[i][3] = -(w2o_[i][0] * A[0][3] + w2o_[i][1] * A[1][3] + w2o_[i][2] * A[2][3]);
  isSimilarity_ = isSimilarityTransform(objectToWorld_, &worldScale_);
  worldCenter_ = objectToWorld_(Point3f(0, 0, 0));
  worldRadius_ = radius_ * worldScale_;
}

Bounds3f SphereShape::objectBound() const {
  // The draft's bound ignores phiMax (lrt draft §3.2.1); that is conservative.
  return Bounds3f(Point3f(-radius_, -radius_, zMin_), Point3f(radius_, radius_, zMax_));
}

Bounds3f SphereShape::worldBound() const {
  // Each corner is padded by its transformation error bound so the world box stays
  // conservative: Embree culls the user geometry by this box (pbrt 3e §3.9.4).
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

// Relative error bound of a 3-term dot product plus a constant in double (pbrt 3e §3.9.1,
// with double's unit roundoff).
constexpr double kDoubleGamma4 = 4 * (std::numeric_limits<double>::epsilon() / 2) /
                                 (1 - 4 * (std::numeric_limits<double>::epsilon() / 2));

bool SphereShape::findHit(const Ray& r, Hit* hit) const {
  if (!invertible_) return false;
  // To object space in double, with the bound of that arithmetic's own rounding (the float ray
  // is exact input).
  double o[3], d[3], oErr[3], dErr[3];
  for (int i = 0; i < 3; ++i) {
    const double* m = w2o_[i];
    o[i] = m[0] * r.o.x + m[1] * r.o.y + m[2] * r.o.z + m[3];
    d[i] = m[0] * r.d.x + m[1] * r.d.y + m[2] * r.d.z;
    oErr[i] = kDoubleGamma4 * (std::abs(m[0] * r.o.x) + std::abs(m[1] * r.o.y) +
                               std::abs(m[2] * r.o.z) + std::abs(m[3]));
    dErr[i] =
        kDoubleGamma4 * (std::abs(m[0] * r.d.x) + std::abs(m[1] * r.d.y) + std::abs(m[2] * r.d.z));
  }

  // The quadratic |o + t d|^2 = r^2 (lrt draft §3.2.2), with the discriminant taken from the
  // distance between the centre and the line, which keeps its precision for rays from far away
  // (pbrt 4e §6.8.2: b^2 - 4ac = 4a (r + l)(r - l)).
  double rad = radius_;
  double a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  double b = 2 * (d[0] * o[0] + d[1] * o[1] + d[2] * o[2]);
  double c = o[0] * o[0] + o[1] * o[1] + o[2] * o[2] - rad * rad;
  double f = b / (2 * a);
  double vx = o[0] - f * d[0], vy = o[1] - f * d[1], vz = o[2] - f * d[2];
  double len = std::sqrt(vx * vx + vy * vy + vz * vz);
  double discrim = 4 * a * (rad + len) * (rad - len);
  if (!(discrim >= 0)) return false;  // also NaN and infinite rays, and d = 0
  double root = std::sqrt(discrim);
  double q = (b < 0) ? -0.5 * (b - root) : -0.5 * (b + root);
  if (q == 0) return false;
  double roots[2] = {q / a, c / q};
  if (roots[0] > roots[1]) std::swap(roots[0], roots[1]);

  for (double t : roots) {
    Float tf = Float(t);
    if (!(tf < r.tMax)) return false;
    double p[3] = {o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]};
    // A root no farther than the uncertainty of t is the surface the ray leaves: the first
    // order sensitivity of t to the errors of o and d, dt = -p.(do + t dd) / p.d. This is pbrt
    // 3e's conservative "t lower bound > 0" test (§3.9.6) for our double arithmetic.
    double sens = 0, pDotD = 0;
    for (int i = 0; i < 3; ++i) {
      sens += std::abs(p[i]) * (oErr[i] + std::abs(t) * dErr[i]);
      pDotD += p[i] * d[i];
    }
    if (!(t * std::abs(pDotD) > 2 * sens) || !(tf > 0)) continue;
    // Reproject onto the surface (pbrt 3e §3.9.4) and guard the pole, where phi is undefined
    // (pbrt 3e §3.2.2).
    double scale = rad / std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    for (double& pi : p) pi *= scale;
    if (p[0] == 0 && p[1] == 0) p[0] = 1e-5 * rad;
    Float phi = Float(std::atan2(p[1], p[0]));
    if (phi < 0) phi += 2 * kPi;
    // Partial spheres: clip by z range and sweep angle, then retry the far root.
    if ((zMin_ > -radius_ && p[2] < zMin_) || (zMax_ < radius_ && p[2] > zMax_)) continue;
    if (phiMax_ < 2 * kPi && phi > phiMax_) continue;
    hit->t = tf;
    std::copy(p, p + 3, hit->p);
    hit->phi = phi;
    return true;
  }
  return false;
}

Point3f SphereShape::toWorld(const double p[3], Vector3f* pError) const {
  // The double result is within kDoubleGamma4 of the exact image of p; rounding it to float
  // adds at most half an ulp. gamma(2) covers that with room to spare.
  Point3f pw;
  for (int i = 0; i < 3; ++i) {
    const double* m = o2w_[i];
    double v = m[0] * p[0] + m[1] * p[1] + m[2] * p[2] + m[3];
    double err = kDoubleGamma4 * (std::abs(m[0] * p[0]) + std::abs(m[1] * p[1]) +
                                  std::abs(m[2] * p[2]) + std::abs(m[3]));
    pw[i] = Float(v);
    (*pError)[i] = gamma(2) * std::abs(pw[i]) + nextFloatUp(Float(err));
  }
  return pw;
}

bool SphereShape::intersectP(const Ray& ray) const {
  Hit hit;
  return findHit(ray, &hit);
}

bool SphereShape::intersect(const Ray& ray, Float* tHit, SurfaceInteraction* isect) const {
  Hit hit;
  if (!findHit(ray, &hit)) return false;
  *tHit = hit.t;
  if (!isect) return true;

  // Parametric representation (lrt draft §3.2.3): phi = u phiMax, theta = lerp(v, thetaMin,
  // thetaMax).
  Point3f p(Float(hit.p[0]), Float(hit.p[1]), Float(hit.p[2]));
  Float u = hit.phi / phiMax_;
  Float cosTheta = clamp(p.z / radius_, -1, 1);
  Float theta = std::acos(cosTheta);
  Float dTheta = thetaZMax_ - thetaZMin_;
  Float v = dTheta != 0 ? (theta - thetaZMin_) / dTheta : 0;
  // sin(theta) from the distance to the axis is accurate near the poles.
  Float zRadius = Float(std::sqrt(hit.p[0] * hit.p[0] + hit.p[1] * hit.p[1]));
  Float sinTheta = zRadius / radius_;
  Float cosPhi = p.x / zRadius, sinPhi = p.y / zRadius;
  Vector3f dpdu(-phiMax_ * p.y, phiMax_ * p.x, 0);
  Vector3f dpdv = dTheta * Vector3f(p.z * cosPhi, p.z * sinPhi, -radius_ * sinTheta);

  // Normal derivatives from the Weingarten equations (lrt draft §3.2.4): second derivatives of
  // p, the fundamental forms' coefficients E F G and e f g, then dn/du, dn/dv.
  Vector3f d2Pduu = -phiMax_ * phiMax_ * Vector3f(p.x, p.y, 0);
  Vector3f d2Pduv = dTheta * p.z * phiMax_ * Vector3f(-sinPhi, cosPhi, 0);
  Vector3f d2Pdvv = -dTheta * dTheta * Vector3f(p);
  Float E = dot(dpdu, dpdu), F = dot(dpdu, dpdv), G = dot(dpdv, dpdv);
  Vector3f c = cross(dpdu, dpdv);
  Normal3f dndu, dndv;
  Float egf2 = E * G - F * F;
  if (c.lengthSquared() > 0 && egf2 != 0) {
    Vector3f N = normalize(c);
    Float e = dot(N, d2Pduu), f = dot(N, d2Pduv), g = dot(N, d2Pdvv);
    Float inv = 1 / egf2;
    dndu = Normal3f(dpdu * ((f * F - e * G) * inv) + dpdv * ((e * F - f * E) * inv));
    dndv = Normal3f(dpdu * ((g * F - f * G) * inv) + dpdv * ((f * F - g * E) * inv));
  }

  Vector3f pErr;
  Point3f pWorld = toWorld(hit.p, &pErr);
  Vector3f wo = -ray.d;
  Float woLen = wo.length();
  if (woLen > 0) wo = wo / woLen;
  // The world cross product flips under a mirroring transform; the xor restores the outward
  // side, which ReverseOrientation then turns around (lrt draft §2.8, pbrt 3e §2.10.1).
  *isect = SurfaceInteraction(pWorld, pErr, Point2f(u, v), wo, objectToWorld_(dpdu),
                              objectToWorld_(dpdv), objectToWorld_(dndu), objectToWorld_(dndv),
                              ray.time, reverseOrientation_ != transformSwapsHandedness_);
  return true;
}

Float SphereShape::area() const {
  return phiMax_ * radius_ * (zMax_ - zMin_) * worldScale_ * worldScale_;
}

Interaction SphereShape::sample(const Point2f& u, Float* pdf) const {
  double z = lerp(u.x, zMin_, zMax_);
  double phi = u.y * phiMax_;
  double rxy = std::sqrt(std::max(0.0, double(radius_) * radius_ - z * z));
  double pObj[3] = {rxy * std::cos(phi), rxy * std::sin(phi), z};
  Vector3f pErr;
  Point3f p = toWorld(pObj, &pErr);
  // The normal transformed as a normal stays outward under mirrors; only ReverseOrientation
  // flips it.
  Normal3f n = normalize(objectToWorld_(Normal3f(Float(pObj[0]), Float(pObj[1]), Float(pObj[2]))));
  if (reverseOrientation_) n = -n;
  Float a = area();
  *pdf = a > 0 ? 1 / a : 0;
  return Interaction(p, n, pErr, Vector3f(), 0);
}

bool SphereShape::refInside(const Interaction& ref) const {
  Point3f pOrigin = ref.offsetOrigin(worldCenter_ - ref.p);
  return distanceSquared(pOrigin, worldCenter_) <= worldRadius_ * worldRadius_;
}

Interaction SphereShape::sample(const Interaction& ref, const Point2f& u, Float* pdf) const {
  if (!usesConeSampling() || refInside(ref)) {
    Interaction it = Shape::sample(ref, u, pdf);
    it.time = ref.time;
    return it;
  }
  // Uniform over the cone of directions that hit the sphere (lrt draft §15.6.3). 1 - cos is
  // taken as sin^2 / (1 + cos), which keeps its precision for distant, tiny spheres.
  Vector3f toCenter = worldCenter_ - ref.p;
  Float dc2 = toCenter.lengthSquared(), dc = std::sqrt(dc2);
  Float sinThetaMax2 = std::min(Float(1), worldRadius_ * worldRadius_ / dc2);
  Float sinThetaMax = std::sqrt(sinThetaMax2);
  Float cosThetaMax = safeSqrt(1 - sinThetaMax2);
  Float oneMinusCosMax = sinThetaMax2 / (1 + cosThetaMax);
  Float oneMinusCos = u.x * oneMinusCosMax;
  Float cosTheta = 1 - oneMinusCos;
  Float sinTheta2 = oneMinusCos * (2 - oneMinusCos);
  Float phi = u.y * 2 * kPi;

  // Rather than intersecting the sampled ray with the sphere, find the point directly: by the
  // law of sines the angle alpha at the centre between the sample and the direction back to
  // ref satisfies cos(alpha) = sin^2/sinMax + cos sqrt(1 - sin^2/sinMax^2) (pbrt 3e §14.2.2,
  // in the form of pbrt 4e §6.2.4).
  Float cosAlpha = sinTheta2 / sinThetaMax + cosTheta * safeSqrt(1 - sinTheta2 / sinThetaMax2);
  Float sinAlpha = safeSqrt(1 - cosAlpha * cosAlpha);
  Vector3f wc = toCenter / dc, wcX, wcY;
  coordinateSystem(wc, &wcX, &wcY);
  Vector3f nWorld =
      wcX * (-sinAlpha * std::cos(phi)) + wcY * (-sinAlpha * std::sin(phi)) - wc * cosAlpha;

  // The point in object space on the sphere (to double precision), then back with its bound.
  double pObj[3], len2 = 0;
  for (int i = 0; i < 3; ++i) {
    pObj[i] = w2o_[i][0] * nWorld.x + w2o_[i][1] * nWorld.y + w2o_[i][2] * nWorld.z;
    len2 += pObj[i] * pObj[i];
  }
  for (double& c : pObj) c *= radius_ / std::sqrt(len2);
  Vector3f pErr;
  Point3f p = toWorld(pObj, &pErr);
  Normal3f n = normalize(Normal3f(nWorld));
  if (reverseOrientation_) n = -n;
  *pdf = 1 / (2 * kPi * oneMinusCosMax);
  return Interaction(p, n, pErr, Vector3f(), ref.time);
}

Float SphereShape::pdf(const Interaction& ref, const Vector3f& wi) const {
  if (!usesConeSampling() || refInside(ref)) return Shape::pdf(ref, wi);
  // Zero for directions that miss the sphere: the line must pass within the radius of the
  // centre, ahead of ref (the cross product is in double precision).
  Vector3f toCenter = worldCenter_ - ref.p;
  Float wiLen2 = wi.lengthSquared();
  if (!(wiLen2 > 0) || dot(toCenter, wi) <= 0) return 0;
  Float perp2 = cross(toCenter, wi).lengthSquared() / wiLen2;
  Float r2 = worldRadius_ * worldRadius_;
  if (perp2 > r2) return 0;
  Float sinThetaMax2 = std::min(Float(1), r2 / toCenter.lengthSquared());
  Float cosThetaMax = safeSqrt(1 - sinThetaMax2);
  return 1 / (2 * kPi * (sinThetaMax2 / (1 + cosThetaMax)));
}

std::unique_ptr<Shape> createSphereShape(const Transform& objectToWorld, bool reverseOrientation,
                                         const ParamSet& params) {
  Float radius = params.getOneFloat("radius", 1);
  if (!(radius > 0) || !std::isfinite(radius))
    throw SceneError(
        params.locationOf("radius", FileLoc()),
        "sphere \"radius\" must be positive and finite, found " + std::to_string(radius));
  Float zMin = params.getOneFloat("zmin", -radius);
  Float zMax = params.getOneFloat("zmax", radius);
  // pbrt's "phimax"; the lrt draft (App. C) calls the same angle "thetamax".
  Float phiMax = params.find("phimax") ? params.getOneFloat("phimax", 360)
                                       : params.getOneFloat("thetamax", 360);
  return std::make_unique<SphereShape>(objectToWorld, reverseOrientation, radius, zMin, zMax,
                                       phiMax);
}

}  // namespace candela
