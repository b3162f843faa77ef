// The perspective (pinhole or thin-lens) camera (lrt draft §6.2; pbrt-v2 PerspectiveCamera).
// Raster (0,0) is the image's top-left corner; the screen window spans the image, and the fov is
// the angle the window's [-1, 1] range subtends, so by default it applies to the shorter axis.
#pragma once

#include "cameras/projective_camera.h"

namespace candela {

struct PerspectiveCameraOptions : ProjectiveCameraOptions {
  Float fov = 90;  // degrees, across the screen window's [-1, 1]
};

class PerspectiveCamera final : public ProjectiveCamera, public CameraImportance {
 public:
  PerspectiveCamera(const AnimatedTransform& cameraToWorld,
                    const PerspectiveCameraOptions& options);
  const PerspectiveCameraOptions& options() const { return perspectiveOptions_; }
  const char* kind() const override { return "perspective"; }

  // Importance (pbrt 3e §16.1.1), normalised so that ∫∫ We cos θ dω dA = 1 over the lens and the
  // film: We = 1 / (A_film A_lens cos⁴θ) for a direction at angle θ to the axis whose pinhole ray
  // lands on the film, A_film the film's area on the plane z = 1 in camera space, A_lens = π r²
  // (1 for a pinhole, whose lens is a Dirac point). Assumes cameraToWorld does not scale.
  const CameraImportance* importance() const override { return this; }
  Spectrum We(const Ray& ray, Point2f* pRaster) const override;
  void pdfWe(const Ray& ray, Float* pdfPos, Float* pdfDir) const override;
  CameraWiSample sampleWi(const Interaction& ref, const Point2f& u) const override;
  Point3f lensPoint(const Ray& ray) const override;
  Vector3f axis(Float time) const override;

 private:
  // The camera-space lens point and unit direction of a world ray, and cos θ (0 when the ray
  // does not leave the lens forward).
  Float toCamera(const Ray& ray, Point3f* pLens, Vector3f* d) const;
  // The raster position of a camera-space ray from the lens; false off the film.
  bool rasterOf(const Point3f& pLens, const Vector3f& d, Point2f* pRaster) const;
  Float lensArea() const;

  PerspectiveCameraOptions perspectiveOptions_;
};

}  // namespace candela
