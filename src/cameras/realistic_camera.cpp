#include "cameras/realistic_camera.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace candela {

namespace {

// The lens with the stop narrowed to the aperture asked for (never widened past the file's).
LensSystem stoppedDown(std::vector<LensInterface> lens, double apertureDiameter) {
  for (LensInterface& e : lens)
    if (e.isStop()) e.apertureRadius = std::min(e.apertureRadius, apertureDiameter / 2);
  return LensSystem(std::move(lens));
}

LensSystem focused(LensSystem lens, double focusDistance) {
  double d = lens.filmDistanceFocusing(focusDistance);
  if (!(d > 0))
    throw std::runtime_error("focusing at " + std::to_string(focusDistance) +
                             " m puts the film inside the lens (" + std::to_string(d * 1000) +
                             " mm behind the rear element)");
  lens.setFilmDistance(d);
  return lens;
}

// The film's width for its diagonal and the image's aspect ratio.
double filmWidth(double diagonal, const Point2i& res) {
  double aspect = double(res.y) / double(res.x);
  return std::sqrt(diagonal * diagonal / (1 + aspect * aspect));
}

}  // namespace

RealisticCamera::RealisticCamera(const AnimatedTransform& cameraToWorld,
                                 const RealisticCameraOptions& options)
    : options_(options),
      cameraToWorld_(cameraToWorld),
      lens_(focused(stoppedDown(options.lens, options.apertureDiameter), options.focusDistance)),
      filmWidth_(filmWidth(options.filmDiagonal, options.fullResolution)),
      filmHeight_(filmWidth_ * double(options.fullResolution.y) / double(options.fullResolution.x)),
      pupil_(lens_, options.filmDiagonal / 2) {}

LensVector RealisticCamera::filmPoint(const Point2f& pRaster) const {
  double sx = double(pRaster.x) / options_.fullResolution.x;
  double sy = double(pRaster.y) / options_.fullResolution.y;
  // The lens inverts the image: the top row of pixels lies at -y on the film, the left column
  // at +x.
  return {(0.5 - sx) * filmWidth_, (sy - 0.5) * filmHeight_, 0};
}

Float RealisticCamera::generateRay(const CameraSample& sample, Ray* ray) const {
  LensVector pFilm = filmPoint(sample.pFilm);
  double boundsArea;
  LensVector pRear = pupil_.sample(pFilm.x, pFilm.y, sample.pLens.x, sample.pLens.y, &boundsArea);
  LensRay fromFilm{pFilm, pRear - pFilm}, out;
  if (!lens_.traceFromFilm(fromFilm, &out)) return 0;

  Float time = options_.shutterOpen + sample.time * (options_.shutterClose - options_.shutterOpen);
  Transform toWorld = cameraToWorld_.interpolate(time);
  Point3f o = toWorld(Point3f(Float(out.o.x), Float(out.o.y), Float(-out.o.z)));
  Vector3f d = toWorld(Vector3f(Float(out.d.x), Float(out.d.y), Float(-out.d.z)));
  *ray = Ray(o, normalize(d), kInfinity, time);

  // Irradiance at the film point: E = ∫ L cos⁴θ / z² dA over the rear plane at distance z, here
  // sampled uniformly over the pupil's bounds (pbrt 3e §6.4.7).
  double cosTheta = std::abs(fromFilm.d.z) / fromFilm.d.length();
  double cos4 = (cosTheta * cosTheta) * (cosTheta * cosTheta);
  if (options_.simpleWeighting) return Float(cos4 * boundsArea / pupil_.interval(0).area());
  double z = lens_.rearZ();
  return Float(double(options_.shutterClose - options_.shutterOpen) * cos4 * boundsArea / (z * z));
}

}  // namespace candela
