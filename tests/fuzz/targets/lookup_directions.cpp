#include "fuzz/targets/lookup_directions.h"

#include <cmath>

namespace candela::fuzz {

const std::vector<std::pair<Vector3f, Vector3f>>& lookupDirections() {
  static const std::vector<std::pair<Vector3f, Vector3f>> pairs = [] {
    std::vector<Vector3f> dirs = {Vector3f(0, 0, 1),
                                  Vector3f(1, 0, 0),
                                  Vector3f(0, -1, 0),
                                  normalize(Vector3f(1, 1, 1)),
                                  normalize(Vector3f(-1, 0.2f, 0.1f)),
                                  normalize(Vector3f(0.3f, -0.4f, 1e-6f))};
    std::vector<std::pair<Vector3f, Vector3f>> p;
    for (const Vector3f& a : dirs)
      for (const Vector3f& b : dirs) {
        p.emplace_back(a, b);
        p.emplace_back(a, -b);
      }
    return p;
  }();
  return pairs;
}

}  // namespace candela::fuzz
