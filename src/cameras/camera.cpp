#include "cameras/camera.h"

namespace candela {

Float Camera::generateRayDifferential(const CameraSample& sample, RayDifferential* ray) const {
  // Finite differences one pixel over (pbrt 3e §6.1.1): correct for any camera, if slower than
  // the analytic differentials a projective camera can compute.
  Ray main;
  Float weight = generateRay(sample, &main);
  *ray = RayDifferential(main);
  if (weight == 0) return 0;
  CameraSample shifted = sample;
  shifted.pFilm.x += 1;
  Ray rx;
  Float wx = generateRay(shifted, &rx);
  shifted = sample;
  shifted.pFilm.y += 1;
  Ray ry;
  Float wy = generateRay(shifted, &ry);
  if (wx == 0 || wy == 0) return weight;  // no differentials past the image's edge of validity
  *ray = RayDifferential(main, rx, ry);
  return weight;
}

}  // namespace candela
