// Pseudo-random numbers: PCG32 (O'Neill 2014), and hashing used to seed a generator from
// (pixel, sample index, seed) so that every sample is reproducible on its own.
#pragma once

#include <cstdint>
#include <initializer_list>

#include "core/common.h"

namespace candela {

// 64-bit finaliser of MurmurHash3: a bijective mix with good avalanche.
inline uint64_t mixBits(uint64_t v) {
  v ^= v >> 33;
  v *= 0xff51afd7ed558ccdULL;
  v ^= v >> 33;
  v *= 0xc4ceb9fe1a85ec53ULL;
  v ^= v >> 33;
  return v;
}

inline uint64_t hashValues(std::initializer_list<uint64_t> values) {
  uint64_t h = 0x9e3779b97f4a7c15ULL;
  for (uint64_t v : values) h = mixBits(h ^ (v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2)));
  return h;
}

class RNG {
 public:
  RNG() { setSequence(0, 0x853c49e6748fea9bULL); }
  explicit RNG(uint64_t sequence, uint64_t seed = 0x853c49e6748fea9bULL) {
    setSequence(sequence, seed);
  }
  void setSequence(uint64_t sequence, uint64_t seed) {
    state_ = 0u;
    inc_ = (sequence << 1u) | 1u;
    uniformUInt32();
    state_ += seed;
    uniformUInt32();
  }
  uint32_t uniformUInt32() {
    uint64_t old = state_;
    state_ = old * 0x5851f42d4c957f2dULL + inc_;
    uint32_t xorshifted = uint32_t(((old >> 18u) ^ old) >> 27u);
    uint32_t rot = uint32_t(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((~rot + 1u) & 31));
  }
  // Uniform in [0, bound) without modulo bias.
  uint32_t uniformUInt32(uint32_t bound) {
    uint32_t threshold = (~bound + 1u) % bound;
    for (;;) {
      uint32_t r = uniformUInt32();
      if (r >= threshold) return r % bound;
    }
  }
  // Uniform in [0, 1).
  Float uniformFloat() { return std::min(kOneMinusEpsilon, Float(uniformUInt32()) * 0x1p-32f); }

 private:
  uint64_t state_ = 0, inc_ = 0;
};

// The i-th element of a pseudo-random permutation of [0, n) chosen by seed: a bijective mix on
// the next power-of-two range, cycle-walking until the value falls inside [0, n).
inline uint32_t permutationElement(uint32_t i, uint32_t n, uint64_t seed) {
  if (n <= 1) return 0;
  uint32_t bits = 32 - __builtin_clz(n - 1);
  uint64_t mask = (uint64_t(1) << bits) - 1;
  uint64_t v = i;
  do {
    // Each step is a bijection on [0, 2^bits): xor with a key, odd multiply, xorshift.
    for (int round = 0; round < 3; ++round) {
      uint64_t key = mixBits(seed + uint64_t(round) * 0x9e3779b97f4a7c15ULL);
      v ^= key & mask;
      v = (v * ((key >> 32) | 1)) & mask;
      v ^= v >> ((bits + 1) / 2);
    }
  } while (v >= n);
  return uint32_t(v);
}

}  // namespace candela
