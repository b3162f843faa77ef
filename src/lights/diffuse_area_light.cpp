#include "lights/diffuse_area_light.h"

#include "core/sampling.h"

namespace candela {

Spectrum DiffuseAreaLight::sampleLi(const Interaction& ref, const Point2f& u, Vector3f* wi,
                                    Float* pdf, VisibilityTester* vis) const {
  // The point is written where the shadow ray will read it, with the direction the shape found.
  vis->p1 = shape_->sampleFrom(ref, u, pdf, wi);
  if (*pdf == 0) return Spectrum(0);
  vis->p1.time = ref.time;
  vis->p0 = ref;
  return L(vis->p1, -*wi);
}

}  // namespace candela

namespace candela {

// A point uniform by area on the shape and a cosine-distributed direction about its normal
// (pbrt 3e §16.1); a two-sided light first picks a side with uDir.x, so the direction density is
// half the cosine density on either side.
Spectrum DiffuseAreaLight::sampleLe(const Point2f& uPos, const Point2f& uDir, Float time, Ray* ray,
                                    Normal3f* nLight, Float* pdfPos, Float* pdfDir) const {
  Interaction pShape = shape_->sample(uPos, pdfPos);
  if (*pdfPos == 0) {
    *pdfDir = 0;
    return Spectrum(0);
  }
  pShape.time = time;
  Point2f u = uDir;
  Float side = 1;
  if (twoSided_) {
    if (u.x < Float(0.5)) {
      u.x = std::min(u.x * 2, kOneMinusEpsilon);
    } else {
      u.x = std::min((u.x - Float(0.5)) * 2, kOneMinusEpsilon);
      side = -1;
    }
  }
  Vector3f local = sampleCosineHemisphere(u);
  Vector3f n(pShape.n);
  n = n * side;
  Vector3f v1, v2;
  coordinateSystem(n, &v1, &v2);
  Vector3f d = v1 * local.x + v2 * local.y + n * local.z;
  *pdfDir = cosineHemispherePdf(local.z) * (twoSided_ ? Float(0.5) : Float(1));
  *ray = pShape.spawnRay(d);
  *nLight = pShape.n;
  return L(pShape, d);
}

void DiffuseAreaLight::pdfLe(const Ray& ray, const Normal3f& nLight, Float* pdfPos,
                             Float* pdfDir) const {
  *pdfPos = 1 / shape_->area();
  Float cosTheta = dot(nLight, ray.d) / ray.d.length();
  if (twoSided_)
    *pdfDir = Float(0.5) * cosineHemispherePdf(std::abs(cosTheta));
  else
    *pdfDir = cosTheta > 0 ? cosineHemispherePdf(cosTheta) : 0;
}

std::optional<LightBounds> DiffuseAreaLight::bounds() const {
  LightBounds b;
  b.bounds = shape_->worldBound();
  Float y = lEmit_.y() * shape_->area();
  b.phi = std::isfinite(y) && y > 0 ? 4 * kPi * y : 0;
  DirectionCone normals = shape_->normalBound();
  b.w = normals.w;
  b.cosThetaO = normals.cosTheta;
  b.cosThetaE = 0;  // Lambertian: out to 90° from the normal
  b.twoSided = twoSided_;
  return b;
}

}  // namespace candela
