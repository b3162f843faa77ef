#include "cameras/perspective_camera.h"

namespace candela {

// The projection Scale(1/tan(fov/2)) maps camera (x, y, 1) to screen (x, y) / tan(fov/2) (lrt
// draft §6.2.1), so the pinhole ray through screen point s has direction (s tan(fov/2), 1) from
// the origin.
PerspectiveCamera::PerspectiveCamera(const AnimatedTransform& cameraToWorld,
                                     const PerspectiveCameraOptions& options)
    : ProjectiveCamera(cameraToWorld, options, 0, std::tan(radians(options.fov) / 2)),
      perspectiveOptions_(options) {}

}  // namespace candela
