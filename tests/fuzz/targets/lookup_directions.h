// Pairs of directions at which the measured-BRDF fuzz targets look their tables up: the poles,
// grazing directions, the same and opposite azimuths, both hemispheres.
#pragma once

#include <utility>
#include <vector>

#include "core/vector.h"

namespace candela::fuzz {

const std::vector<std::pair<Vector3f, Vector3f>>& lookupDirections();

}  // namespace candela::fuzz
