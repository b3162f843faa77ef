// The Sobol' sequence in base 2 (pbrt 3e §7.7; Sobol' 1967): coordinate d of point n is the
// product of a 32 x 32 generator matrix over GF(2) with n's binary digits, the result read as a
// binary fraction. Dimension 0's matrix is the identity mirrored (van der Corput); dimensions
// 1 to kSobolDimensions - 1 have matrices from Joe & Kuo's direction numbers (Joe & Kuo 2008,
// "Constructing Sobol sequences with better two-dimensional projections", their table
// new-joe-kuo-6.21201, dimensions 2 to 128). Every matrix is upper triangular with a unit
// diagonal, so the first 2^k values of each coordinate put one value in every interval
// [j/2^k, (j+1)/2^k); dimensions 0 and 1 together are a (0,2)-sequence.
#pragma once

#include <cstdint>

namespace candela {

inline constexpr int kSobolDimensions = 128;

// Coordinate `dimension` (0 <= dimension < kSobolDimensions) of point `index` as a 32-bit binary
// fraction (bit 31 the first digit).
uint32_t sobolBits(uint32_t index, int dimension);

}  // namespace candela
