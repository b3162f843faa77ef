#include "lights/projection_light.h"

namespace candela {

ProjectionLight::ProjectionLight(const Transform& lightToWorld, const Spectrum& intensity,
                                 Float fovDeg, std::shared_ptr<const MIPMap<Spectrum>> image,
                                 Float aspect)
    : lightToWorld_(lightToWorld),
      worldToLight_(inverse(lightToWorld)),
      position_(lightToWorld(Point3f(0, 0, 0))),
      intensity_(intensity),
      image_(std::move(image)),
      tanHalfFov_(std::tan(radians(clamp(fovDeg, Float(1e-3), Float(179.9))) / 2)) {
  if (!(aspect > 0)) aspect = 1;
  screenX_ = aspect > 1 ? aspect : 1;
  screenY_ = aspect > 1 ? 1 : 1 / aspect;
}

Spectrum ProjectionLight::projection(const Vector3f& wWorld) const {
  Vector3f wl = worldToLight_(wWorld);
  // Behind (or in) the projector's image plane: the perspective divide is meaningless.
  if (!(wl.z > 0)) return Spectrum(0);
  // Screen coordinates of the perspective projection: the fov's half-angle maps to 1.
  Float x = wl.x / (wl.z * tanHalfFov_), y = wl.y / (wl.z * tanHalfFov_);
  if (x < -screenX_ || x > screenX_ || y < -screenY_ || y > screenY_) return Spectrum(0);
  if (!image_) return Spectrum(1);
  Float s = (x + screenX_) / (2 * screenX_);
  Float t = (y + screenY_) / (2 * screenY_);  // top row (t = 0) toward -y, as pbrt-v2/v3
  return image_->lookupTrilinear(Point2f(s, t), 0);
}

Spectrum ProjectionLight::sampleLi(const Interaction& ref, const Point2f&, Vector3f* wi, Float* pdf,
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
  return intensity_ * projection(-*wi) / dist2;
}

std::optional<LightBounds> ProjectionLight::bounds() const {
  Float tx = screenX_ * tanHalfFov_, ty = screenY_ * tanHalfFov_;
  Float cosHalfDiagonal = 1 / std::sqrt(1 + tx * tx + ty * ty);
  Spectrum mean = image_ ? image_->average() : Spectrum(1);
  return pointSourceBounds(position_, intensity_ * mean,
                           worldConeOfLightZ(lightToWorld_, cosHalfDiagonal));
}

Spectrum ProjectionLight::power() const {
  // Half-angles of the pyramid along x and y; sin α from tan α.
  Float tx = screenX_ * tanHalfFov_, ty = screenY_ * tanHalfFov_;
  Float sinA = tx / std::sqrt(1 + tx * tx), sinB = ty / std::sqrt(1 + ty * ty);
  Float solidAngle = 4 * std::asin(sinA * sinB);
  Spectrum mean = image_ ? image_->average() : Spectrum(1);
  return intensity_ * mean * solidAngle;
}

}  // namespace candela

namespace candela {

// Emission directions: a point uniform on the window at distance 1 (pbrt 3e §16.1 samples the
// cone around the window instead, which wastes samples outside it). A plane patch dA at z = 1 seen
// along a direction of angle θ to +z covers dω = cos³θ dA, so the solid-angle density is
// 1 / (A cos³θ) for window area A.
Float ProjectionLight::directionPdf(const Vector3f& wWorld) const {
  Vector3f wl = worldToLight_(wWorld);
  Float len = wl.length();
  if (!(wl.z > 0) || len == 0) return 0;
  Float x = wl.x / (wl.z * tanHalfFov_), y = wl.y / (wl.z * tanHalfFov_);
  if (x < -screenX_ || x > screenX_ || y < -screenY_ || y > screenY_) return 0;
  Float cosTheta = wl.z / len;
  Float area = 4 * screenX_ * screenY_ * tanHalfFov_ * tanHalfFov_;
  return 1 / (area * cosTheta * cosTheta * cosTheta);
}

Spectrum ProjectionLight::sampleLe(const Point2f&, const Point2f& uDir, Float time, Ray* ray,
                                   Normal3f* nLight, Float* pdfPos, Float* pdfDir) const {
  Float x = (2 * uDir.x - 1) * screenX_ * tanHalfFov_;
  Float y = (2 * uDir.y - 1) * screenY_ * tanHalfFov_;
  Vector3f d = normalize(lightToWorld_(Vector3f(x, y, 1)));
  *ray = Ray(position_, d, kInfinity, time);
  *nLight = Normal3f(d.x, d.y, d.z);
  *pdfPos = 1;
  *pdfDir = directionPdf(d);
  return *pdfDir > 0 ? intensity_ * projection(d) : Spectrum(0);
}

void ProjectionLight::pdfLe(const Ray& ray, const Normal3f&, Float* pdfPos, Float* pdfDir) const {
  *pdfPos = 1;
  *pdfDir = directionPdf(ray.d);
}

}  // namespace candela
