#include "samplers/radical_inverse.h"

#include "core/rng.h"

namespace candela {

namespace {

// b^-D <= 2^-26: below half a Float ulp of any value in [0.5, 1) and a quarter of one in
// [0.25, 0.5).
constexpr uint64_t kResolution = uint64_t(1) << 26;

// D, the digits of the expansion in base b, and b^D.
int expansionDigits(uint32_t base, uint64_t* scale) {
  int digits = 0;
  for (*scale = 1; *scale < kResolution; *scale *= base) ++digits;
  return digits;
}

uint64_t power(uint32_t base, int e) {
  uint64_t p = 1;
  while (e-- > 0) p *= base;
  return p;
}

// The maps (a_i, c_i) of a key's digits, in order (see scrambledRadicalInverse).
class DigitMaps {
 public:
  static constexpr int kMaxDigits = 26;  // D for base 2; fewer for larger bases

  DigitMaps(uint32_t base, uint64_t key, int digits)
      : base_(base),
        digits_(digits),
        key_(key),
        offsets_(mixBits(key ^ 0x3c6ef372fe94f82bULL)),
        factors_(mixBits(key ^ 0xa54ff53a5f1d36f1ULL)) {}

  void next(uint32_t* a, uint32_t* c) {
    if (index_ < digits_) {
      // The next digit of each stream: the integer part of the fraction times the radix.
      unsigned __int128 o = static_cast<unsigned __int128>(offsets_) * base_;
      unsigned __int128 f = static_cast<unsigned __int128>(factors_) * (base_ - 1);
      *c = uint32_t(o >> 64);
      *a = 1 + uint32_t(f >> 64);
      offsets_ = uint64_t(o);
      factors_ = uint64_t(f);
    } else {
      uint64_t h = mixBits(key_ + uint64_t(index_ + 1) * 0x9e3779b97f4a7c15ULL);
      *a = 1 + uint32_t(((h & 0xffffffffu) * (base_ - 1)) >> 32);
      *c = uint32_t(((h >> 32) * base_) >> 32);
    }
    ++index_;
  }

  // sum_{i >= k}^{D-1} c_i b^(D-1-i) after k digits were taken: the offset stream's next D - k
  // digits as one number (scale = b^(D-k)).
  uint64_t remainingOffsets(uint64_t scale) const {
    return uint64_t((static_cast<unsigned __int128>(offsets_) * scale) >> 64);
  }

 private:
  uint32_t base_;
  int digits_, index_ = 0;
  uint64_t key_, offsets_, factors_;
};

// setKey's table when indices below the count have k > 1 digits, the maps of digit 0 taken: out
// of line, so that setKey's one-entry case needs no frame for the arrays.
[[gnu::noinline]] void tabulateDigits(DigitMaps& maps, uint32_t base, int k, uint64_t tailScale,
                                      uint32_t size, uint64_t* table) {
  // Digits 1 .. K-1 are the table index's digits 0 .. K-2; the ones from K on are zeros of every
  // index below the count, scrambled to their offsets.
  uint32_t a[DigitMaps::kMaxDigits], c[DigitMaps::kMaxDigits];
  uint64_t weight[DigitMaps::kMaxDigits];
  maps.next(&a[1], &c[1]);  // k > 1: there is a digit 1
  for (int i = 2; i < k; ++i) maps.next(&a[i], &c[i]);
  uint64_t v0 = maps.remainingOffsets(tailScale);
  // Digit i's weight in V is b^(D-1-i): b^(D-K) for the last tabulated one, times b below.
  for (int i = k - 1, w = 0; i >= 1; --i, ++w) {
    weight[i] = w == 0 ? tailScale : weight[i + 1] * base;
    v0 += c[i] * weight[i];
  }
  table[0] = v0;
  // Entries 1 .. b-1 differ from entry 0 in their lowest digit (digit 1 of n) alone: one entry
  // per image, with no block to copy (for bases above the count's square root the only level).
  uint64_t block = std::min<uint64_t>(base, size);
  uint32_t image = c[1];
  for (uint64_t q = 1; q < block; ++q) {
    image += a[1];
    if (image >= base) image -= base;
    table[q] = v0 + (uint64_t(image) - c[1]) * weight[1];  // modulo 2^64: may be "negative"
  }
  // Indices [d b^j, (d+1) b^j) differ from [0, b^j) only in digit j (digit j + 1 of n).
  for (int i = 2; i < k; ++i) {
    image = c[i];
    for (uint32_t d = 1; d < base && d * block < size; ++d) {
      image += a[i];
      if (image >= base) image -= base;
      uint64_t delta = (uint64_t(image) - c[i]) * weight[i];
      uint64_t first = d * block, end = std::min<uint64_t>(first + block, size);
      for (uint64_t q = first; q < end; ++q) table[q] = table[q - first] + delta;
    }
    block *= base;
  }
}

}  // namespace

Float radicalInverse(uint32_t n, uint32_t base) {
  double invBase = 1.0 / double(base), digitWeight = invBase, value = 0;
  while (n > 0) {
    value += double(n % base) * digitWeight;
    n /= base;
    digitWeight *= invBase;
  }
  return std::min(Float(value), kOneMinusEpsilon);
}

Float scrambledRadicalInverse(uint32_t n, uint32_t base, uint64_t key) {
  uint64_t scale;
  int digits = expansionDigits(base, &scale);
  DigitMaps maps(base, key, digits);
  // Horner's rule, the lowest digit of n first: its image is the highest digit of V.
  uint64_t v = 0;
  scale = 1;
  for (int i = 0; n > 0 || i < digits; ++i) {
    uint32_t a, c;
    maps.next(&a, &c);
    v = v * base + (a * (n % base) + c) % base;
    n /= base;
    scale *= base;
  }
  return std::min(Float(double(v) * (1.0 / double(scale))), kOneMinusEpsilon);
}

FastScrambledRadicalInverse::FastScrambledRadicalInverse(uint32_t base, uint32_t count)
    : reciprocal_(~uint64_t(0) / base + 1), base_(base) {
  uint64_t scale;
  int digits = expansionDigits(base, &scale);
  count_ = uint32_t(std::min<uint64_t>(std::max(count, 1u), scale));
  int fast = 1;
  for (uint32_t m = count_ - 1; m >= base; m /= base) ++fast;
  digits_ = uint8_t(digits);
  fastDigits_ = uint8_t(fast);
  tableSize_ = (count_ + base - 1) / base;
  lowWeight_ = power(base, digits - 1);
  tailScale_ = power(base, digits - fast);
  invScale_ = 1.0 / double(scale);
}

void FastScrambledRadicalInverse::setKey(uint64_t key, uint64_t* table) {
  DigitMaps maps(base_, key, digits_);
  key_ = key;
  uint32_t a0, c0;
  maps.next(&a0, &c0);
  lowFactor_ = reciprocal_ * a0;
  lowOffset_ = reciprocal_ * c0;
  // Indices below the count of one digit (a base above the count; most of them): the one entry
  // is what the digits above the lowest, all zeros, contribute.
  if (fastDigits_ == 1)
    table[0] = maps.remainingOffsets(tailScale_);
  else
    tabulateDigits(maps, base_, fastDigits_, tailScale_, tableSize_, table);
}

}  // namespace candela
