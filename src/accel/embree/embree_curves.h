// Curve pieces (pbrt 3e §3.7) as Embree's native curves: each piece is one cubic Bézier
// primitive with its radius (half the width) per control point, flat curves as Embree's
// ray-facing flat curves, cylinders as round curves (a swept circle, open at the curve's ends),
// ribbons as normal-oriented curves. Internal to src/accel/embree.
#pragma once

#include <embree3/rtcore.h>

#include <cstdint>
#include <vector>

#include "accel/primitive.h"
#include "shapes/curve_shape.h"

namespace candela {

// A new, uncommitted curve geometry of the given type holding, as primitive k, the CurveShape
// of primitives[primIndex[k]] (all of that type). Returns nullptr on an Embree error (the
// device's error state says which).
RTCGeometry newCurveGeometry(RTCDevice device, CurveType type, const Primitive* primitives,
                             const std::vector<uint32_t>& primIndex);

}  // namespace candela
