// Radical inverses in prime bases (lrt draft §7.5.2): Phi_b(n) mirrors n's base-b digits about
// the radix point, so Phi_2(1..5) = .5, .25, .75, .125, .625. The Halton sequence uses the first
// primes as bases, one per dimension.
#pragma once

#include <algorithm>
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

// Phi_b(n) with each digit d_i (i = 0, 1, ...; d_0 the lowest) replaced by its image under a
// pseudo-random permutation of the digits chosen by (key, i): the affine map (a_i d + c_i) mod b
// with a_i in [1, b), c_i in [0, b), a permutation because b is prime (random linear digit
// scrambling, Matousek 1998). Digits past n's last become c_i, not 0, so the expansion runs on
// to the D-th digit, where b^-D <= 2^-26 no longer changes a Float in [0.25, 1), as with the
// draft's folded radical inverse. Scrambling keeps Phi_b's stratification: the first b^m values
// of n still put one value in each interval [j/b^m, (j+1)/b^m).
//
// The maps of the first D digits come from two hashes of the key: c_0, c_1, ... are the base-b
// digits of one as a binary fraction, a_i - 1 the base-(b-1) digits of the other (the digits of a
// uniform number are independent and uniform); digits past D hash (key, i) each. The value is
// exact before its one rounding: V = sum_i pi_i(d_i) b^(E-1-i) is an integer (E = max(D, n's
// digit count), V < 2^45) and the result is V times the double 1 / b^E, rounded to a Float.
// base: a prime below 2^16.
Float scrambledRadicalInverse(uint32_t n, uint32_t base, uint64_t key);

// scrambledRadicalInverse in one base, fast for indices below a count (the samples of a pixel),
// for one key at a time: setKey makes the key's table of what the digits above the lowest
// contribute (one entry per b indices, one addition each); a value is then a table entry plus the
// lowest digit's image, with no hash or division (see tabulatedValue). Equal to
// scrambledRadicalInverse bit for bit.
class FastScrambledRadicalInverse {
 public:
  FastScrambledRadicalInverse(uint32_t base, uint32_t count);
  uint32_t base() const { return base_; }
  // Entries of a key's table: ceil(count / base).
  uint32_t tableSize() const { return tableSize_; }
  // Makes key's table (tableSize() entries) and keeps what value() needs of the key.
  void setKey(uint64_t key, uint64_t* table);

  Float value(uint32_t n, const uint64_t* table) const {
    if (n >= count_) return scrambledRadicalInverse(n, base_, key_);
    return tabulatedValue(n, table);
  }
  // value(n) for n below the count: the caller knows it is. Two multiplications by 2^64 / b
  // (its ceiling M): the high 64 bits of M n are n / b, and the low 64 bits of M x are the
  // fraction of x / b, whose product with b has x mod b as its high 64 bits (both exact for x
  // below 2^32: Lemire, Kaser and Kurz 2019). The lowest digit's image (a_0 d_0 + c_0) mod b is
  // (a_0 n + c_0) mod b, below 2^32 for n below the count, so M (a_0 n + c_0) = (M a_0) n +
  // M c_0 modulo 2^64, two products setKey keeps.
  Float tabulatedValue(uint32_t n, const uint64_t* table) const {
    uint64_t lowFraction = lowFactor_ * n + lowOffset_;
    uint64_t v = table[highBits(reciprocal_, n)] + highBits(lowFraction, base_) * lowWeight_;
    Float x = Float(double(int64_t(v)) * invScale_);  // v < 2^45
    return x < kOneMinusEpsilon ? x : kOneMinusEpsilon;
  }
  // The count the tables cover: min(count, b^D), at least 1.
  uint32_t count() const { return count_; }

 private:
  static uint64_t highBits(uint64_t a, uint64_t b) {
    return uint64_t((static_cast<unsigned __int128>(a) * b) >> 64);
  }

  // What tabulatedValue reads, first (one cache line).
  uint64_t reciprocal_;     // M = ceil(2^64 / b)
  uint64_t lowFactor_ = 0;  // M a_0 modulo 2^64 (a_0, c_0: the lowest digit's map under the key)
  uint64_t lowOffset_ = 0;  // M c_0 modulo 2^64
  uint64_t lowWeight_;      // b^(D-1), the lowest digit's weight in V
  double invScale_;         // 1 / b^D
  uint32_t base_;
  // What value() past the count and setKey read.
  uint32_t count_;
  uint64_t key_ = 0;
  uint64_t tailScale_;  // b^(D-K)
  uint32_t tableSize_;
  uint8_t digits_;      // D
  uint8_t fastDigits_;  // K: the digits of count - 1 (at least 1)
};

}  // namespace candela
