// The measured-BRDF fuzz targets' check: a table the reader accepted gives finite, non-negative
// values at pairs of directions that cover the poles, grazing directions, the same and opposite
// azimuths, and both hemispheres.
#pragma once

#include <functional>
#include <vector>

#include "core/spectrum.h"
#include "core/vector.h"

namespace candela::fuzz {

// The directions the checks pair: the poles, grazing directions and both hemispheres.
const std::vector<Vector3f>& lookupDirections();

using BrdfLookup = std::function<Spectrum(const Vector3f& wo, const Vector3f& wi)>;

// Calls broken(what) when a lookup is negative, NaN or infinite.
void checkLookups(const BrdfLookup& lookup, const char* what);

}  // namespace candela::fuzz
