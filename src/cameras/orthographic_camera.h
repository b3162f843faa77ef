// The orthographic camera (lrt draft §6.2.1; pbrt-v2 OrthoCamera): parallel rays along camera +z
// from the film points, which are the screen window's points on the plane z = 0 (the projection
// Orthographic(n, f) = Scale(1, 1, 1/(f-n)) Translate(0, 0, -n) leaves x and y unchanged). By
// default the window is [-1, 1] along the shorter image axis, so the image covers two units of
// world space there. A lens (lensradius > 0) blurs what is off the plane z = focaldistance.
#pragma once

#include "cameras/projective_camera.h"

namespace candela {

class OrthographicCamera final : public ProjectiveCamera {
 public:
  const char* kind() const override { return "orthographic"; }
  OrthographicCamera(const AnimatedTransform& cameraToWorld,
                     const ProjectiveCameraOptions& options);
};

}  // namespace candela
