// Nested uniform scrambling in base 2 (Owen 1995; pbrt 4e §8.7.4): digit i of a binary fraction
// is flipped or not by a random choice that depends on the digits before it. The scrambled
// points of a (t,m,s)-net are again a (t,m,s)-net, each point uniform on [0,1)^s, so estimates
// stay unbiased while keeping the net's stratification. The choices come from a hash instead of
// a stored tree (Burley 2020, "Practical Hash-based Owen Scrambling", JCGT 9(4)): with the digits
// reversed, the first digit is the lowest bit, and adding the seed or XOR-ing in the value times
// an even constant changes each bit by a function of the bits below it only, i.e. of the digits
// before it. The four constants are Burley's.
#pragma once

#include <cstdint>

#include "samplers/zero_two_sequence.h"

namespace candela {

inline uint32_t owenScrambleBits(uint32_t bits, uint32_t seed) {
  uint32_t v = reverseBits32(bits);
  v += seed;
  v ^= v * 0x6c50b47cu;
  v ^= v * 0xb82f1e52u;
  v ^= v * 0xc7afe638u;
  v ^= v * 0x8d22f6e6u;
  return reverseBits32(v);
}

}  // namespace candela
