// Which cached samples may stand in for the irradiance at a point, and with what weight
// (pbrt 2e §15.5.2, after Tabellion & Lamorlette 2004): the error of a sample is the larger of
// its distance over its radius and its normal's angle against the largest angle allowed; its
// weight is 1 - error. Ward, Rubinstein & Clear (1988) also reject a sample lying in front of the
// point (the point may be in a crease the sample never saw).
#pragma once

#include "integrators/irradiance/irradiance_octree.h"

namespace candela {

// The weight of sample at (p, n); 0 when it may not be used.
Float interpolationWeight(const IrradianceSample& sample, const Point3f& p, const Normal3f& n,
                          Float cosMaxAngle);

struct InterpolatedIrradiance {
  Spectrum weightedSum = Spectrum(0);
  Float sumWeight = 0;
  // pbrt-v2's rule: enough weight that a few high-error samples cannot make up the value.
  bool acceptable(Float minWeight) const { return sumWeight > 0 && sumWeight >= minWeight; }
  Spectrum E() const { return weightedSum / sumWeight; }
};

InterpolatedIrradiance interpolateIrradiance(const IrradianceOctree& cache, const Point3f& p,
                                             const Normal3f& n, Float cosMaxAngle);

}  // namespace candela
