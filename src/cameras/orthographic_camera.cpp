#include "cameras/orthographic_camera.h"

namespace candela {

// The pinhole ray through screen point s starts at (s, 0) and runs along +z.
OrthographicCamera::OrthographicCamera(const AnimatedTransform& cameraToWorld,
                                       const ProjectiveCameraOptions& options)
    : ProjectiveCamera(cameraToWorld, options, 1, 0) {}

}  // namespace candela
