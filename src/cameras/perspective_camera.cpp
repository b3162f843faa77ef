#include "cameras/perspective_camera.h"

#include "core/sampling.h"

namespace candela {

// The projection Scale(1/tan(fov/2)) maps camera (x, y, 1) to screen (x, y) / tan(fov/2) (lrt
// draft §6.2.1), so the pinhole ray through screen point s has direction (s tan(fov/2), 1) from
// the origin.
PerspectiveCamera::PerspectiveCamera(const AnimatedTransform& cameraToWorld,
                                     const PerspectiveCameraOptions& options)
    : ProjectiveCamera(cameraToWorld, options, 0, std::tan(radians(options.fov) / 2)),
      perspectiveOptions_(options) {}

}  // namespace candela

namespace candela {

Float PerspectiveCamera::lensArea() const {
  Float r = perspectiveOptions_.lensRadius;
  return r > 0 ? kPi * r * r : 1;
}

Float PerspectiveCamera::toCamera(const Ray& ray, Point3f* pLens, Vector3f* d) const {
  Transform toWorld, toCameraT;
  transformsAt(ray.time, &toWorld, &toCameraT);
  Vector3f dc = toCameraT(ray.d);
  Float len = dc.length();
  if (!(len > 0)) return 0;
  *d = dc / len;
  if (!(d->z > 0)) return 0;
  // Back along the ray to the lens plane z = 0 (camera rays start at the near plane).
  Point3f o = toCameraT(ray.o);
  *pLens = o - *d * (o.z / d->z);
  return d->z;
}

bool PerspectiveCamera::rasterOf(const Point3f& pLens, const Vector3f& d, Point2f* pRaster) const {
  // Every ray through a lens point meets the pinhole ray of its raster position on the plane of
  // focus (lrt draft §6.2.3); a pinhole's rays all leave the origin.
  Vector3f pinhole = d / d.z;
  if (perspectiveOptions_.lensRadius > 0) {
    Float f = perspectiveOptions_.focalDistance;
    Point3f pFocus = pLens + pinhole * f;
    pinhole = Vector3f(pFocus.x / f, pFocus.y / f, 1);
  }
  *pRaster = rasterOfPinholeDirection(pinhole);
  const Point2i& res = perspectiveOptions_.fullResolution;
  return pRaster->x >= 0 && pRaster->x < Float(res.x) && pRaster->y >= 0 &&
         pRaster->y < Float(res.y);
}

Spectrum PerspectiveCamera::We(const Ray& ray, Point2f* pRaster) const {
  Point3f pLens;
  Vector3f d;
  Float cosTheta = toCamera(ray, &pLens, &d);
  Point2f raster;
  if (cosTheta == 0 || !rasterOf(pLens, d, &raster)) return Spectrum(0);
  if (pRaster) *pRaster = raster;
  Float cos2 = cosTheta * cosTheta;
  return Spectrum(1 / (pinholeFilmArea() * lensArea() * cos2 * cos2));
}

void PerspectiveCamera::pdfWe(const Ray& ray, Float* pdfPos, Float* pdfDir) const {
  Point3f pLens;
  Vector3f d;
  Point2f raster;
  Float cosTheta = toCamera(ray, &pLens, &d);
  if (cosTheta == 0 || !rasterOf(pLens, d, &raster)) {
    *pdfPos = *pdfDir = 0;
    return;
  }
  // Film positions are uniform on the plane z = 1, where dω = cos³θ dA.
  *pdfPos = 1 / lensArea();
  *pdfDir = 1 / (pinholeFilmArea() * cosTheta * cosTheta * cosTheta);
}

CameraWiSample PerspectiveCamera::sampleWi(const Interaction& ref, const Point2f& u) const {
  CameraWiSample s;
  Transform toWorld, toCameraT;
  transformsAt(ref.time, &toWorld, &toCameraT);
  Point2f lens = sampleUniformDiskConcentric(u) * perspectiveOptions_.lensRadius;
  Point3f pLens = toWorld(Point3f(lens.x, lens.y, 0));
  Vector3f n = normalize(toWorld(Vector3f(0, 0, 1)));
  Vector3f toLens = pLens - ref.p;
  Float dist2 = toLens.lengthSquared();
  if (!(dist2 > 0)) return s;
  s.wi = toLens / std::sqrt(dist2);
  s.pLens = Interaction(pLens, Normal3f(n.x, n.y, n.z), Vector3f(0, 0, 0), -s.wi, ref.time);
  s.We = We(Ray(pLens, -s.wi, kInfinity, ref.time), &s.pRaster);
  // Lens area density to solid angle at ref.
  Float cosLens = absDot(n, s.wi);
  s.pdf = cosLens > 0 ? dist2 / (cosLens * lensArea()) : 0;
  if (s.We.isBlack()) s.pdf = 0;
  return s;
}

Point3f PerspectiveCamera::lensPoint(const Ray& ray) const {
  Transform toWorld, toCameraT;
  transformsAt(ray.time, &toWorld, &toCameraT);
  Point3f o = toCameraT(ray.o);
  Vector3f d = toCameraT(ray.d);
  if (d.z == 0) return ray.o;
  return toWorld(o - d * (o.z / d.z));
}

Vector3f PerspectiveCamera::axis(Float time) const {
  Transform toWorld, toCameraT;
  transformsAt(time, &toWorld, &toCameraT);
  return normalize(toWorld(Vector3f(0, 0, 1)));
}

}  // namespace candela
