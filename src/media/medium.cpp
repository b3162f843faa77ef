#include "media/medium.h"

#include <cmath>

namespace candela {

Spectrum Medium::opticalDepth(const Ray& ray, Float t0, Float t1, Float stepSize,
                              Float offset) const {
  // Midpoint-style ray marching (lrt draft §12.3): n equal steps of at most stepSize, σt sampled
  // at offset into each, so that averaging over a random offset is unbiased.
  Float length = (t1 - t0) * ray.d.length();
  if (!(length > 0)) return Spectrum(0);
  int n = std::max(1, int(std::ceil(length / std::max(stepSize, Float(1e-6) * length))));
  Float dt = (t1 - t0) / Float(n);
  Spectrum tau(0);
  for (int i = 0; i < n; ++i) tau += at(ray(t0 + (Float(i) + offset) * dt), ray.time).sigmaT();
  return tau * (length / Float(n));
}

}  // namespace candela
