#include "samplers/radical_inverse.h"

#include "core/rng.h"

namespace candela {

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
  double invBase = 1.0 / double(base), digitWeight = invBase, value = 0;
  // 2^-26 is below half a Float ulp of any value in [0.5, 1) and below a quarter of one in
  // [0.25, 0.5); the remaining digits together weigh less than b times the current weight.
  for (uint64_t i = 0; n > 0 || digitWeight * double(base) > 0x1p-26; ++i) {
    uint64_t h = mixBits(key + (i + 1) * 0x9e3779b97f4a7c15ULL);
    uint64_t a = 1 + (h & 0xffffffffu) % (base - 1);  // base >= 2
    uint64_t c = (h >> 32) % base;
    uint64_t digit = (a * (n % base) + c) % base;
    value += double(digit) * digitWeight;
    n /= base;
    digitWeight *= invBase;
  }
  return std::min(Float(value), kOneMinusEpsilon);
}

}  // namespace candela
