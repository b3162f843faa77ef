// Test helper: random rays for the aggregate and shape tests, from a seeded RNG.
#pragma once

#include "core/rng.h"
#include "core/sampling.h"

namespace candela::test {

// Uniform on the unit sphere. The two draws are sequenced: as two arguments of one call their order
// would be unspecified.
inline Vector3f randomDirection(RNG& rng) {
  Float u0 = rng.uniformFloat();
  return sampleUniformSphere(Point2f(u0, rng.uniformFloat()));
}

// Uniform in the cube [lo, hi]^3.
inline Point3f randomPoint(RNG& rng, Float lo, Float hi) {
  Float x = lerp(rng.uniformFloat(), lo, hi), y = lerp(rng.uniformFloat(), lo, hi);
  return Point3f(x, y, lerp(rng.uniformFloat(), lo, hi));
}

}  // namespace candela::test
