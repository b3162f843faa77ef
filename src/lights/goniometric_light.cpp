#include "lights/goniometric_light.h"

#include "core/sampling.h"

namespace candela {

GoniometricLight::GoniometricLight(const Transform& lightToWorld, const Spectrum& intensity,
                                   std::shared_ptr<const MIPMap<Spectrum>> image)
    : worldToLight_(inverse(lightToWorld)),
      position_(lightToWorld(Point3f(0, 0, 0))),
      intensity_(intensity),
      image_(std::move(image)) {}

Spectrum GoniometricLight::scale(const Vector3f& wWorld) const {
  if (!image_) return Spectrum(1);
  Vector3f w = worldToLight_(wWorld);
  Float len = w.length();
  if (len == 0) return Spectrum(0);
  w = w / len;
  std::swap(w.y, w.z);  // y up in the diagram (see the header)
  Float theta = std::acos(clamp(w.z, -1, 1));
  Float phi = std::atan2(w.y, w.x);
  if (phi < 0) phi += 2 * kPi;
  return image_->lookupTrilinear(Point2f(phi * kInv2Pi, theta * kInvPi), 0);
}

Spectrum GoniometricLight::sampleLi(const Interaction& ref, const Point2f&, Vector3f* wi,
                                    Float* pdf, VisibilityTester* vis) const {
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
  return intensity_ * scale(-*wi) / dist2;
}

Spectrum GoniometricLight::power() const {
  if (!image_) return intensity_ * (4 * kPi);
  int w = image_->levelWidth(0), h = image_->levelHeight(0);
  Spectrum sum(0);
  for (int j = 0; j < h; ++j) {
    // Row j spans θ in [jπ/h, (j+1)π/h]: solid angle (cos θ0 - cos θ1) 2π / w per texel.
    Float cell = (std::cos(kPi * j / h) - std::cos(kPi * (j + 1) / h)) * (2 * kPi / w);
    for (int i = 0; i < w; ++i) sum += image_->texel(0, i, j) * cell;
  }
  return intensity_ * sum;
}

}  // namespace candela

namespace candela {

// Uniform directions over the sphere, weighted by the diagram (pbrt 3e §16.1).
Spectrum GoniometricLight::sampleLe(const Point2f&, const Point2f& uDir, Float time, Ray* ray,
                                    Normal3f* nLight, Float* pdfPos, Float* pdfDir) const {
  Vector3f d = sampleUniformSphere(uDir);
  *ray = Ray(position_, d, kInfinity, time);
  *nLight = Normal3f(d.x, d.y, d.z);
  *pdfPos = 1;
  *pdfDir = uniformSpherePdf();
  return intensity_ * scale(d);
}

void GoniometricLight::pdfLe(const Ray&, const Normal3f&, Float* pdfPos, Float* pdfDir) const {
  *pdfPos = 1;
  *pdfDir = uniformSpherePdf();
}

}  // namespace candela
