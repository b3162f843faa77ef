// One irradiance cache entry (pbrt 2e §15.5.2): the irradiance E over the hemisphere around n
// at p, from indirect light only, and the radius within which it may stand in for the
// irradiance at other points.
#pragma once

#include "core/spectrum.h"
#include "core/vector.h"

namespace candela {

struct IrradianceSample {
  Point3f p;
  Normal3f n;  // unit; the hemisphere's axis
  Spectrum E;
  Float radius = 0;
};

}  // namespace candela
