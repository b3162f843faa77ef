#include "fuzz/targets/lookup_directions.h"

#include <cmath>

#include "fuzz/targets/fuzz_targets.h"

namespace candela::fuzz {

const std::vector<Vector3f>& lookupDirections() {
  static const std::vector<Vector3f> dirs = {Vector3f(0, 0, 1),
                                             Vector3f(1, 0, 0),
                                             Vector3f(0, -1, 0),
                                             normalize(Vector3f(1, 1, 1)),
                                             normalize(Vector3f(-1, 0.2f, 0.1f)),
                                             normalize(Vector3f(0.3f, -0.4f, 1e-6f))};
  return dirs;
}

void checkLookups(const BrdfLookup& lookup, const char* what) {
  const std::vector<Vector3f>& dirs = lookupDirections();
  for (const Vector3f& a : dirs)
    for (const Vector3f& b : dirs)
      for (const Vector3f& wi : {b, -b}) {
        Spectrum f = lookup(a, wi);
        for (int c = 0; c < 3; ++c)
          if (!(f[c] >= 0) || !std::isfinite(f[c])) broken(what);
      }
}

}  // namespace candela::fuzz
