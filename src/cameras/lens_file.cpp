#include "cameras/lens_file.h"

#include <cmath>

#include "core/error.h"
#include "core/number_lines.h"

namespace candela {

std::vector<LensInterface> readLensFile(const std::string& path) {
  std::vector<LensInterface> interfaces;
  readNumberLines(path, [&](int lineNo, const std::vector<double>& v) {
    auto fail = [&](const std::string& what) {
      throw FileError(path + ":" + std::to_string(lineNo), what);
    };
    if (interfaces.size() == kMaxLensInterfaces)
      fail("more than " + std::to_string(kMaxLensInterfaces) +
           " interfaces (real lenses have a few dozen; the camera traces its exit pupil through "
           "every one)");
    if (v.size() != 4)
      fail(
          "expected 4 numbers (curvature radius, thickness, index of refraction, aperture "
          "diameter), found " +
          std::to_string(v.size()));
    if (v[1] < 0) fail("negative thickness " + std::to_string(v[1]));
    if (v[2] < 0) fail("negative index of refraction " + std::to_string(v[2]));
    if (!(v[3] > 0)) fail("the aperture diameter must be positive, got " + std::to_string(v[3]));
    // A spherical cap is at most as wide as its sphere.
    if (v[0] != 0 && v[3] > 2 * std::abs(v[0]))
      fail("aperture diameter " + std::to_string(v[3]) + " exceeds the sphere's diameter " +
           std::to_string(2 * std::abs(v[0])));
    LensInterface e;
    e.curvatureRadius = v[0] * 1e-3;
    e.thickness = v[1] * 1e-3;
    e.eta = v[2] == 0 ? 1 : v[2];
    e.apertureRadius = v[3] * 0.5e-3;
    interfaces.push_back(e);
  });
  if (interfaces.empty()) throw FileError(path, "no lens interfaces");
  return interfaces;
}

}  // namespace candela
