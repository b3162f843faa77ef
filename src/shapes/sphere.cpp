#include "shapes/sphere.h"

#include "core/sampling.h"

namespace candela {

SphereShape::SphereShape(const Transform& objectToWorld, bool reverseOrientation, Float radius,
                         Float zMin, Float zMax, Float phiMaxDeg)
    : Quadric(objectToWorld, reverseOrientation),
      radius_(radius),
      zMin_(clamp(std::min(zMin, zMax), -radius, radius)),
      zMax_(clamp(std::max(zMin, zMax), -radius, radius)),
      thetaZMin_(std::acos(clamp(zMin_ / radius_, -1.0, 1.0))),
      thetaZMax_(std::acos(clamp(zMax_ / radius_, -1.0, 1.0))),
      phiMax_(phiMaxRadians(phiMaxDeg)),
      isFullSphere_(zMin_ <= -radius_ && zMax_ >= radius_ && phiMaxDeg >= 360) {
  // phiMax r (zMax - zMin): a zone's area is proportional to its height (pbrt 3e §3.2.5).
  objectArea_ = phiMax_ * radius_ * (zMax_ - zMin_);
  worldCenter_ = this->objectToWorld()(Point3f(0, 0, 0));
  worldRadius_ = Float(radius_ * worldScale());
  const double origin[3] = {0, 0, 0};
  setBoundingBall(origin, radius_);  // for every zone and sweep
}

Bounds3f SphereShape::objectBound() const {
  // The draft's bound ignores phiMax (lrt draft §3.2.1); that is conservative.
  Float r = Float(radius_);
  return Bounds3f(Point3f(-r, -r, Float(zMin_)), Point3f(r, r, Float(zMax_)));
}

void SphereShape::lineCoefficients(const double o[3], const double d[3], double* a, double* b,
                                   double* c) const {
  // |o + t d|^2 - r^2 (lrt draft §3.2.2). Quadric moves o to the point of the line nearest the
  // centre, so c = |o|^2 - r^2 keeps the precision of pbrt 4e's (r + l)(r - l) (§6.8.2).
  *a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  *b = 2 * (d[0] * o[0] + d[1] * o[1] + d[2] * o[2]);
  *c = o[0] * o[0] + o[1] * o[1] + o[2] * o[2] - radius_ * radius_;
}

double SphereShape::implicit(const double p[3], double* fErr, double grad[3]) const {
  double p2 = p[0] * p[0] + p[1] * p[1] + p[2] * p[2], r2 = radius_ * radius_;
  *fErr = 3 * std::numeric_limits<double>::epsilon() * (p2 + r2);
  for (int i = 0; i < 3; ++i) grad[i] = 2 * p[i];
  return p2 - r2;
}

bool SphereShape::clip(double p[3]) const {
  // Back onto the sphere (pbrt 3e §3.9.4), then the z range and the sweep. The z test applies
  // only to a cut sphere: a pole hit a rounding error beyond +-r stays on a full one.
  double scale = radius_ / std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
  for (int i = 0; i < 3; ++i) p[i] *= scale;
  if ((zMin_ > -radius_ && p[2] < zMin_) || (zMax_ < radius_ && p[2] > zMax_)) return false;
  return phiMax_ >= 2 * std::numbers::pi || azimuth(p[0], p[1]) <= phiMax_;
}

Quadric::LocalGeometry SphereShape::geometryAt(const double p[3]) const {
  double rho = std::sqrt(p[0] * p[0] + p[1] * p[1]);
  double phi = azimuth(p[0], p[1]), cosPhi = std::cos(phi), sinPhi = std::sin(phi);
  // theta from atan2 is accurate near the poles, where acos(z / r) is not.
  double theta = std::atan2(rho, p[2]), dTheta = thetaZMax_ - thetaZMin_;
  LocalGeometry g;
  g.uv = Point2f(Float(phi / phiMax_), Float(dTheta != 0 ? (theta - thetaZMin_) / dTheta : 0));
  // At a pole phi is undefined and dp/du vanishes: the tangents are taken a little off it, where
  // the distance to the axis is kAxisNudge r (pbrt 3e §3.2.2). r sin theta is that distance.
  double rhoG = std::max(rho, kAxisNudge * radius_), z = p[2];
  double xg = rhoG * cosPhi, yg = rhoG * sinPhi;
  // phi = u phiMax, theta = thetaZMin + v dTheta (lrt draft §3.2.3).
  g.dpdu = Vector3f(Float(-phiMax_ * yg), Float(phiMax_ * xg), 0);
  g.dpdv = Vector3f(Float(dTheta * z * cosPhi), Float(dTheta * z * sinPhi), Float(-dTheta * rhoG));
  g.d2Pduu = Vector3f(Float(-phiMax_ * phiMax_ * xg), Float(-phiMax_ * phiMax_ * yg), 0);
  g.d2Pduv =
      Vector3f(Float(-dTheta * z * phiMax_ * sinPhi), Float(dTheta * z * phiMax_ * cosPhi), 0);
  g.d2Pdvv = Vector3f(Float(-dTheta * dTheta * xg), Float(-dTheta * dTheta * yg),
                      Float(-dTheta * dTheta * z));
  return g;
}

void SphereShape::sampleObject(const Point2f& u, double p[3]) const {
  // z uniform in [zMin, zMax] and phi in [0, phiMax] is uniform by area (Archimedes), so a cut
  // sphere is sampled exactly (the lrt draft, §15.6, samples the whole sphere).
  double z = (1 - double(u.x)) * zMin_ + double(u.x) * zMax_, phi = u.y * phiMax_;
  double rxy = std::sqrt(std::max(0.0, radius_ * radius_ - z * z));
  p[0] = rxy * std::cos(phi);
  p[1] = rxy * std::sin(phi);
  p[2] = z;
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
  double pObj[3];
  toObjectVector(nWorld, pObj);
  double scale = radius_ / std::sqrt(pObj[0] * pObj[0] + pObj[1] * pObj[1] + pObj[2] * pObj[2]);
  for (double& c : pObj) c *= scale;
  Vector3f pErr;
  Point3f p = toWorld(pObj, &pErr);
  Normal3f n = normalize(Normal3f(nWorld));
  if (reverseOrientation()) n = -n;
  *pdf = 1 / (2 * kPi * oneMinusCosMax);
  return Interaction(p, n, pErr, Vector3f(), ref.time);
}

Float SphereShape::pdf(const Interaction& ref, const Vector3f& wi) const {
  if (!usesConeSampling() || refInside(ref)) return Shape::pdf(ref, wi);
  // Zero for directions that miss the sphere: the line must pass within the radius of the
  // centre, ahead of ref.
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
  Float radius = params.getOneFloat("radius", 1, ValueRange::positive(), FileLoc());
  // zmin and zmax must be finite, and are then clamped to the radius.
  Float zMin = params.getOneFloat("zmin", -radius, ValueRange::finite(), FileLoc());
  Float zMax = params.getOneFloat("zmax", radius, ValueRange::finite(), FileLoc());
  return std::make_unique<SphereShape>(objectToWorld, reverseOrientation, radius, zMin, zMax,
                                       quadricPhiMax(params));
}

}  // namespace candela
