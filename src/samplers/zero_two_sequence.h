// The base-2 (0,2)-sequence (lrt draft §7.5.3; Kollig & Keller 2002): the van der Corput
// sequence Phi_2 in the first coordinate and Sobol's second coordinate in the other. Every
// aligned block of 2^k consecutive points is a (0,k,2)-net: each elementary interval
// [a/2^i, (a+1)/2^i) x [b/2^j, (b+1)/2^j) with i + j = k holds exactly one point. Values are kept
// as 32-bit binary fractions so that random digit scrambling is one XOR, which maps every
// elementary interval onto another and so keeps the net property (draft §7.5.3).
#pragma once

#include <cstdint>

#include "core/rng.h"
#include "core/vector.h"

namespace candela {

inline uint32_t reverseBits32(uint32_t v) {
  // Swap halves, then bytes, nibbles, pairs and single bits within them.
  v = (v << 16) | (v >> 16);
  v = ((v & 0x00ff00ffu) << 8) | ((v >> 8) & 0x00ff00ffu);
  v = ((v & 0x0f0f0f0fu) << 4) | ((v >> 4) & 0x0f0f0f0fu);
  v = ((v & 0x33333333u) << 2) | ((v >> 2) & 0x33333333u);
  v = ((v & 0x55555555u) << 1) | ((v >> 1) & 0x55555555u);
  return v;
}

// Phi_2(n): n's binary digits mirrored about the binary point (draft §7.5.2), then scrambled.
inline uint32_t vanDerCorputBits(uint32_t n, uint32_t scramble) {
  return reverseBits32(n) ^ scramble;
}

// Sobol's second dimension: the generator matrix's column for bit j of n is row j of Pascal's
// triangle mod 2, top-aligned (1, 11, 101, 1111, ...); the point is the XOR of the columns of
// n's set bits.
inline uint32_t sobol2Bits(uint32_t n, uint32_t scramble) {
  uint32_t column = 0x80000000u;
  for (; n != 0; n >>= 1) {
    if (n & 1u) scramble ^= column;
    column ^= column >> 1;
  }
  return scramble;
}

// A 32-bit binary fraction as a Float in [0, 1). Only the top 24 bits are kept, so the value is
// exact (and never rounds up to 1) and lies in the same elementary intervals as the fraction.
inline Float bitsToUnitFloat(uint32_t bits) { return Float(bits >> 8) * 0x1p-24f; }

// A pseudo-random permutation of the sample indices [0, 2^log2Count) chosen by key that maps
// every aligned block of 2^j indices onto an aligned block: bit j of the index is flipped or not
// by a hash of the bits above it. Used to pair dimensions up at random (as the draft's shuffles
// do) while each aligned block of samples, in particular the first 2^j of a pixel, stays a net.
// Bits at or above log2Count pass through unchanged and take part in the hash.
inline uint32_t nestedIndexPermutation(uint32_t index, int log2Count, uint64_t key) {
  uint32_t result = index;
  for (int j = log2Count - 1; j >= 0; --j) {
    uint64_t above = uint64_t(index >> (j + 1));
    if (mixBits(key ^ ((above << 5) | uint64_t(j))) >> 63) result ^= 1u << j;
  }
  return result;
}

}  // namespace candela
