#include "lights/spot_light.h"

#include "core/sampling.h"

namespace candela {

namespace {

// The rigid transform taking +z to `dir` (unit): its columns are a frame around dir.
Transform zToDirection(const Vector3f& dir) {
  Vector3f du, dv;
  coordinateSystem(dir, &du, &dv);
  Matrix4x4 m(du.x, dv.x, dir.x, 0, du.y, dv.y, dir.y, 0, du.z, dv.z, dir.z, 0, 0, 0, 0, 1);
  return Transform(m, transpose(m));
}

}  // namespace

SpotLight::SpotLight(const Transform& lightToWorld, const Spectrum& intensity, const Point3f& from,
                     const Point3f& to, Float coneAngle, Float coneDelta)
    : intensity_(intensity),
      cosTotalWidth_(std::cos(radians(coneAngle))),
      cosFalloffStart_(std::cos(radians(coneAngle - coneDelta))) {
  Vector3f axis = to - from;
  // A degenerate from == to keeps the default axis +z rather than producing NaNs.
  axis = axis.lengthSquared() > 0 ? normalize(axis) : Vector3f(0, 0, 1);
  Transform toWorld =
      lightToWorld * translate(Vector3f(from.x, from.y, from.z)) * zToDirection(axis);
  lightToWorld_ = toWorld;
  worldToLight_ = inverse(toWorld);
  position_ = toWorld(Point3f(0, 0, 0));
}

std::optional<LightBounds> SpotLight::bounds() const {
  LightBounds b =
      pointSourceBounds(position_, intensity_, worldConeOfLightZ(lightToWorld_, cosFalloffStart_));
  if (!b.normals().coversEveryDirection())
    b.cosThetaE = std::cos(safeAcos(cosTotalWidth_) - safeAcos(cosFalloffStart_));
  return b;
}

Float SpotLight::falloff(const Vector3f& wWorld) const {
  Vector3f wl = worldToLight_(wWorld);
  Float len = wl.length();
  if (len == 0) return 0;
  Float cosTheta = wl.z / len;
  if (cosTheta < cosTotalWidth_) return 0;
  if (cosTheta >= cosFalloffStart_) return 1;
  Float delta = (cosTheta - cosTotalWidth_) / (cosFalloffStart_ - cosTotalWidth_);
  return (delta * delta) * (delta * delta);
}

Spectrum SpotLight::sampleLi(const Interaction& ref, const Point2f&, Vector3f* wi, Float* pdf,
                             VisibilityTester* vis) const {
  Vector3f d = position_ - ref.p;
  Float dist2 = d.lengthSquared();
  if (dist2 == 0) {
    *pdf = 0;
    return Spectrum(0);
  }
  *wi = d / std::sqrt(dist2);
  *pdf = 1;
  vis->p0 = ref;
  vis->p1 = Interaction(position_, ref.time);
  return intensity_ * (falloff(-*wi) / dist2);
}

Spectrum SpotLight::power() const {
  Float inner = 1 - cosFalloffStart_;
  Float band = std::max(Float(0), cosFalloffStart_ - cosTotalWidth_) / 5;
  return intensity_ * (2 * kPi * (inner + band));
}

}  // namespace candela

namespace candela {

// Directions uniform within the outer cone (pbrt 3e §16.1); the falloff weights them.
Spectrum SpotLight::sampleLe(const Point2f&, const Point2f& uDir, Float time, Ray* ray,
                             Normal3f* nLight, Float* pdfPos, Float* pdfDir) const {
  Vector3f d = normalize(lightToWorld_(sampleUniformCone(uDir, cosTotalWidth_)));
  *ray = Ray(position_, d, kInfinity, time);
  *nLight = Normal3f(d.x, d.y, d.z);
  *pdfPos = 1;
  *pdfDir = uniformConePdf(cosTotalWidth_);
  return intensity_ * falloff(d);
}

void SpotLight::pdfLe(const Ray& ray, const Normal3f&, Float* pdfPos, Float* pdfDir) const {
  Vector3f wl = worldToLight_(ray.d);
  Float len = wl.length();
  *pdfPos = 1;
  *pdfDir = (len > 0 && wl.z / len >= cosTotalWidth_) ? uniformConePdf(cosTotalWidth_) : 0;
}

}  // namespace candela
