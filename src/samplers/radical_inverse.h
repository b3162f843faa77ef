// Radical inverses in prime bases (lrt draft §7.5.2): Phi_b(n) mirrors n's base-b digits about
// the radix point, so Phi_2(1..5) = .5, .25, .75, .125, .625. The Halton sequence uses the first
// primes as bases, one per dimension.
#pragma once

#include <array>
#include <cstdint>

#include "core/common.h"

namespace candela {

inline constexpr int kPrimeTableSize = 1024;

// The first kPrimeTableSize primes (2, 3, 5, ..., 8161), computed at compile time.
inline constexpr std::array<uint32_t, kPrimeTableSize> kPrimes = [] {
  std::array<uint32_t, kPrimeTableSize> primes{};
  int count = 0;
  for (uint32_t candidate = 2; count < kPrimeTableSize; ++candidate) {
    // Stopping at the first divisor keeps the evaluation within clang's constexpr step limit.
    bool prime = true;
    for (int i = 0; prime && i < count && primes[i] * primes[i] <= candidate; ++i)
      prime = candidate % primes[i] != 0;
    if (prime) primes[count++] = candidate;
  }
  return primes;
}();

// Phi_b(n), exact digit by digit in double precision, as a Float in [0, 1).
Float radicalInverse(uint32_t n, uint32_t base);

// Phi_b(n) with each digit d_i (i = 1, 2, ...) replaced by a pseudo-random permutation of the
// digits chosen by (key, i): the affine map (a d + c) mod b with a in [1, b), c in [0, b), a
// permutation because b is prime (random linear digit scrambling, Matousek 1998). Digits past n's
// last become c_i, not 0, so the expansion runs on until they no longer change a Float, as with
// the draft's folded radical inverse. Scrambling keeps Phi_b's stratification: the first b^m
// values of n still put one value in each interval [j/b^m, (j+1)/b^m).
Float scrambledRadicalInverse(uint32_t n, uint32_t base, uint64_t key);

}  // namespace candela
