// pbrt-v3's "realistic" camera (pbrt 3e §6.4, after Kolb et al. 1995): rays from points on the
// film traced through a lens system's spherical elements, sampled over the exit pupil's bounds.
// The film (its diagonal given in millimetres by the Film) is centred on the axis at lens-space
// z = 0 and the image it forms is inverted: raster (0, 0), the image's top-left corner, is the
// film's (+x, -y) corner. The film distance is set by the thick-lens approximation so that points
// focusDistance in front of the film are sharp. The ray leaving the front element is taken to
// camera space by mirroring z (the camera looks down +z).
#pragma once

#include <vector>

#include "cameras/camera.h"
#include "cameras/exit_pupil.h"
#include "cameras/lens_system.h"

namespace candela {

struct RealisticCameraOptions {
  Point2i fullResolution{640, 480};
  std::vector<LensInterface> lens;  // front first, in metres
  double apertureDiameter = 1e-3;   // of the stop (m), at most the lens file's
  double focusDistance = 10;        // from the film (m)
  double filmDiagonal = 0.035;      // m
  // true: weight cos⁴θ scaled by the sampled pupil bounds' area over the film centre's, so that
  // images are near the other cameras' brightness; false: the film's exposure, shutter time x
  // ∫ L cos⁴θ / z² dA over the rear plane (pbrt 3e §6.4.7).
  bool simpleWeighting = true;
  Float shutterOpen = 0, shutterClose = 1;
};

class RealisticCamera final : public Camera {
 public:
  // Throws std::runtime_error when the lens cannot focus at the distance or the focused film
  // would lie inside the lens.
  RealisticCamera(const AnimatedTransform& cameraToWorld, const RealisticCameraOptions& options);
  const char* kind() const override { return "realistic"; }
  Float generateRay(const CameraSample& sample, Ray* ray) const override;
  Float shutterOpen() const override { return options_.shutterOpen; }
  Float shutterClose() const override { return options_.shutterClose; }

  const LensSystem& lens() const { return lens_; }
  const ExitPupil& exitPupil() const { return pupil_; }
  // The lens-space film point (z = 0) of a raster position.
  LensVector filmPoint(const Point2f& pRaster) const;

 private:
  RealisticCameraOptions options_;
  AnimatedTransform cameraToWorld_;
  LensSystem lens_;
  double filmWidth_, filmHeight_;
  ExitPupil pupil_;
};

}  // namespace candela
