#include "integrators/irradiance/irradiance_interpolation.h"

#include <cmath>

namespace candela {

namespace {
// How far in front of the point, as a fraction of the sample's radius, a sample may lie before it
// is rejected: curved surfaces put neighbours slightly off each other's tangent planes.
constexpr Float kInFrontTolerance = 0.05f;
}  // namespace

Float interpolationWeight(const IrradianceSample& sample, const Point3f& p, const Normal3f& n,
                          Float cosMaxAngle) {
  Float cosAngle = dot(n, sample.n);
  if (cosAngle < cosMaxAngle) return 0;
  Vector3f d = p - sample.p;
  Float dist2 = d.lengthSquared();
  if (!(dist2 < sample.radius * sample.radius)) return 0;
  // In front: the sample sits above the point's side of the averaged tangent plane.
  if (dot(d, Vector3f(n + sample.n)) * 0.5f < -kInFrontTolerance * sample.radius) return 0;
  Float positionError = std::sqrt(dist2) / sample.radius;
  Float normalError = std::sqrt(std::max(Float(0), 1 - cosAngle) / (1 - cosMaxAngle));
  Float error = std::max(positionError, normalError);
  return error < 1 ? 1 - error : 0;
}

InterpolatedIrradiance interpolateIrradiance(const IrradianceOctree& cache, const Point3f& p,
                                             const Normal3f& n, Float cosMaxAngle) {
  InterpolatedIrradiance result;
  cache.forEachNear(p, [&](const IrradianceSample& s) {
    Float w = interpolationWeight(s, p, n, cosMaxAngle);
    if (w > 0) {
      result.weightedSum += s.E * w;
      result.sumWeight += w;
    }
  });
  return result;
}

}  // namespace candela
