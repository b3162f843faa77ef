// The perspective (pinhole or thin-lens) camera (lrt draft §6.2; pbrt-v2 PerspectiveCamera).
// Raster (0,0) is the image's top-left corner; the screen window spans the image, and the fov is
// the angle the window's [-1, 1] range subtends, so by default it applies to the shorter axis.
#pragma once

#include "cameras/projective_camera.h"

namespace candela {

struct PerspectiveCameraOptions : ProjectiveCameraOptions {
  Float fov = 90;  // degrees, across the screen window's [-1, 1]
};

class PerspectiveCamera final : public ProjectiveCamera {
 public:
  PerspectiveCamera(const AnimatedTransform& cameraToWorld,
                    const PerspectiveCameraOptions& options);
  const PerspectiveCameraOptions& options() const { return perspectiveOptions_; }

 private:
  PerspectiveCameraOptions perspectiveOptions_;
};

}  // namespace candela
