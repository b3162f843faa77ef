// Even Fourier series in an azimuth difference phi, sum_k a_k cos(k phi) for k < m (pbrt 3e
// §8.6, §8.6.2): evaluation by the recurrence cos(k phi) = 2 cos(phi) cos((k-1) phi) -
// cos((k-2) phi), which needs only cos(phi), and sampling by inverting the series' integral.
#pragma once

#include "core/common.h"

namespace candela {

Float evaluateFourier(const Float* a, int m, double cosPhi);

// Draws phi in [-pi, pi] with density proportional to the series (which should be non-negative):
// phi in [0, pi] by inverting a_0 phi + sum_k a_k sin(k phi) / k, and the sign by u < 1/2.
// Returns false when a_0 <= 0; else *phi, the series there (*value) and the density
// *pdf = value / (2 pi a_0).
bool sampleFourier(const Float* a, int m, Float u, Float* phi, Float* value, Float* pdf);

}  // namespace candela
