#include "lights/infinite_light.h"

namespace candela {

InfiniteAreaLight::InfiniteAreaLight(const Transform& lightToWorld, const Spectrum& radiance,
                                     int nSamples, LatLongMap map)
    : Light(nSamples),
      lightToWorld_(lightToWorld),
      worldToLight_(inverse(lightToWorld)),
      radiance_(radiance),
      map_(std::move(map)) {
  if (map_.width <= 0 || map_.height <= 0) {
    map_ = {};
    return;
  }
  // Luminance times sin θ at the row's centre: the solid angle a texel of that row covers is
  // proportional to it (§15.4), so bright texels near the poles are not oversampled. The radiance
  // inside a texel's cell is interpolated from it and its eight neighbours, so the cell gets their
  // largest luminance: wherever the sky is not black, the pdf is not zero.
  std::vector<Float> func(map_.texels.size());
  for (int j = 0; j < map_.height; ++j) {
    Float sinTheta = std::sin(kPi * (j + Float(0.5)) / map_.height);
    for (int i = 0; i < map_.width; ++i) {
      Float largest = 0;
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) largest = std::max(largest, texel(i + di, j + dj).y());
      func[size_t(j) * size_t(map_.width) + size_t(i)] = largest * sinTheta;
    }
  }
  distribution_ = std::make_unique<Distribution2D>(func, map_.width, map_.height);
}

void InfiniteAreaLight::preprocess(const Bounds3f& sceneBounds) {
  sceneBounds.boundingSphere(&sceneCenter_, &sceneRadius_);
}

const Spectrum& InfiniteAreaLight::texel(int i, int j) const {
  i %= map_.width;
  if (i < 0) i += map_.width;
  j = clamp(j, 0, map_.height - 1);
  return map_.texels[size_t(j) * size_t(map_.width) + size_t(i)];
}

// Bilinear between the four nearest texel centres, as pbrt-v2 and pbrt-v3 look their maps up
// (pbrt 2e §14.6.1, pbrt 3e §12.6): periodic in φ, clamped at the poles.
Spectrum InfiniteAreaLight::interpolated(const Point2f& st) const {
  Float x = st.x * map_.width - Float(0.5), y = st.y * map_.height - Float(0.5);
  Float x0 = std::floor(x), y0 = std::floor(y);
  Float fx = x - x0, fy = y - y0;
  int i = int(x0), j = int(y0);
  return texel(i, j) * ((1 - fx) * (1 - fy)) + texel(i + 1, j) * (fx * (1 - fy)) +
         texel(i, j + 1) * ((1 - fx) * fy) + texel(i + 1, j + 1) * (fx * fy);
}

Point2f InfiniteAreaLight::lookupCoordinates(const Vector3f& w, Float* sinTheta) const {
  Vector3f wl = worldToLight_(w);
  Float len = wl.length();
  if (len == 0) {
    *sinTheta = 0;
    return Point2f(0, 0);
  }
  wl = wl / len;
  Float cosTheta = clamp(wl.z, -1, 1);
  // From x and y rather than sqrt(1 - cos²): accurate near the poles, where the pdf divides by it.
  *sinTheta = std::min(Float(1), std::sqrt(wl.x * wl.x + wl.y * wl.y));
  Float phi = std::atan2(wl.y, wl.x);
  if (phi < 0) phi += 2 * kPi;
  return Point2f(phi * kInv2Pi, std::acos(cosTheta) * kInvPi);
}

Spectrum InfiniteAreaLight::radiance(const Vector3f& w) const {
  if (!distribution_) return radiance_;
  Float sinTheta;
  Point2f st = lookupCoordinates(w, &sinTheta);
  return radiance_ * interpolated(st);
}

Spectrum InfiniteAreaLight::sampleLi(const Interaction& ref, const Point2f& u, Vector3f* wi,
                                     Float* pdf, VisibilityTester* vis) const {
  Spectrum L;
  if (!distribution_) {
    *wi = normalize(lightToWorld_(sampleUniformSphere(u)));
    *pdf = uniformSpherePdf();
    L = radiance_;
  } else {
    Float mapPdf;
    Point2f st = distribution_->sampleContinuous(u, &mapPdf);
    Float theta = st.y * kPi, phi = st.x * 2 * kPi;
    Float sinTheta = std::sin(theta);
    if (mapPdf == 0 || sinTheta == 0) {
      *pdf = 0;
      return Spectrum(0);
    }
    *wi = normalize(lightToWorld_(sphericalDirection(sinTheta, std::cos(theta), phi)));
    *pdf = mapPdf / (2 * kPi * kPi * sinTheta);
    L = radiance_ * interpolated(st);
  }
  // A point beyond the scene's bounding sphere: the shadow ray crosses all geometry.
  Float reach = 2 * sceneRadius_ + distance(ref.p, sceneCenter_);
  vis->p0 = ref;
  vis->p1 = Interaction(ref.p + *wi * reach, ref.time);
  return L;
}

Float InfiniteAreaLight::pdfLi(const Interaction&, const Vector3f& wi) const {
  if (!distribution_) return uniformSpherePdf();
  Float sinTheta;
  Point2f st = lookupCoordinates(wi, &sinTheta);
  if (sinTheta == 0) return 0;
  return distribution_->pdf(st) / (2 * kPi * kPi * sinTheta);
}

Spectrum InfiniteAreaLight::power() const {
  Spectrum integral = radiance_ * (4 * kPi);
  if (distribution_) {
    // ∫ L dω of the interpolated map. Along φ the interpolation is periodic and linear between
    // texel centres, so a row at any θ integrates exactly to 2π / width times the sum of its
    // texels, itself linear in θ between the rows' sums. Along θ: the midpoint rule on strips a
    // quarter of a texel high, each covering (cos θ0 - cos θ1) of solid angle per unit φ.
    std::vector<Spectrum> rowSums(size_t(map_.height), Spectrum(0));
    for (int j = 0; j < map_.height; ++j)
      for (int i = 0; i < map_.width; ++i) rowSums[size_t(j)] += texel(i, j);
    auto rowSum = [&](int j) { return rowSums[size_t(clamp(j, 0, map_.height - 1))]; };
    constexpr int kSub = 4;
    const int strips = map_.height * kSub;
    Spectrum sum(0);
    for (int k = 0; k < strips; ++k) {
      Float y = (k + Float(0.5)) / strips * map_.height - Float(0.5);
      Float y0 = std::floor(y), fy = y - y0;
      Spectrum row = rowSum(int(y0)) * (1 - fy) + rowSum(int(y0) + 1) * fy;
      Float band = std::cos(kPi * k / strips) - std::cos(kPi * (k + 1) / strips);
      sum += row * (band * 2 * kPi / map_.width);
    }
    integral = radiance_ * sum;
  }
  return integral * (kPi * sceneRadius_ * sceneRadius_);
}

}  // namespace candela

namespace candela {

// The direction toward the sky as sampleLi picks it, the origin uniform on the disk of the scene's
// bounding radius R facing it, one R out; the ray travels back into the scene (pbrt 3e §16.1).
Spectrum InfiniteAreaLight::sampleLe(const Point2f& uPos, const Point2f& uDir, Float time, Ray* ray,
                                     Normal3f* nLight, Float* pdfPos, Float* pdfDir) const {
  Vector3f wi;
  VisibilityTester unused;
  Spectrum L = sampleLi(Interaction(sceneCenter_, time), uDir, &wi, pdfDir, &unused);
  if (*pdfDir == 0) {
    *pdfPos = 0;
    return Spectrum(0);
  }
  Vector3f v1, v2;
  coordinateSystem(wi, &v1, &v2);
  Point2f c = sampleUniformDiskConcentric(uPos);
  Point3f o = sceneCenter_ + (wi + v1 * c.x + v2 * c.y) * sceneRadius_;
  *ray = Ray(o, -wi, kInfinity, time);
  *nLight = Normal3f(-wi.x, -wi.y, -wi.z);
  *pdfPos = 1 / (kPi * sceneRadius_ * sceneRadius_);
  return L;
}

void InfiniteAreaLight::pdfLe(const Ray& ray, const Normal3f&, Float* pdfPos, Float* pdfDir) const {
  *pdfDir = pdfLi(Interaction(ray.o, ray.time), -ray.d);
  *pdfPos = 1 / (kPi * sceneRadius_ * sceneRadius_);
}

}  // namespace candela
