// Basic numeric definitions shared by every module.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace candela {

using Float = float;

inline constexpr Float kPi = 3.14159265358979323846f;
inline constexpr Float kInvPi = 0.31830988618379067154f;
inline constexpr Float kInv2Pi = 0.15915494309189533577f;
inline constexpr Float kInv4Pi = 0.07957747154594766788f;
inline constexpr Float kPiOver2 = 1.57079632679489661923f;
inline constexpr Float kPiOver4 = 0.78539816339744830961f;
inline constexpr Float kInfinity = std::numeric_limits<Float>::infinity();
inline constexpr Float kMachineEpsilon = std::numeric_limits<Float>::epsilon() * 0.5f;
// Largest float below one: the upper end of a canonical sample [0, 1).
inline constexpr Float kOneMinusEpsilon = 0x1.fffffep-1f;
// Shadow rays stop this fraction short of their target (pbrt 3e §3.9.5).
inline constexpr Float kShadowEpsilon = 0.0001f;

// Bound on the relative error of n floating-point operations (pbrt 3e §3.9.1).
constexpr Float gamma(int n) { return (n * kMachineEpsilon) / (1 - n * kMachineEpsilon); }

inline Float radians(Float deg) { return (kPi / 180) * deg; }
inline Float degrees(Float rad) { return (180 / kPi) * rad; }

template <typename T, typename U, typename V>
constexpr T clamp(T val, U low, V high) {
  if (val < low) return T(low);
  if (val > high) return T(high);
  return val;
}

// (1 - t) a + t b: exact at both ends.
inline Float lerp(Float t, Float a, Float b) { return (1 - t) * a + t * b; }

inline uint32_t floatToBits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, sizeof(float));
  return u;
}
inline float bitsToFloat(uint32_t u) {
  float f;
  std::memcpy(&f, &u, sizeof(float));
  return f;
}

// The next representable float above / below v (pbrt 3e §3.9.1).
inline float nextFloatUp(float v) {
  if (std::isinf(v) && v > 0.f) return v;
  if (v == -0.f) v = 0.f;
  uint32_t ui = floatToBits(v);
  if (v >= 0)
    ++ui;
  else
    --ui;
  return bitsToFloat(ui);
}
inline float nextFloatDown(float v) {
  if (std::isinf(v) && v < 0.f) return v;
  if (v == 0.f) v = -0.f;
  uint32_t ui = floatToBits(v);
  if (v > 0)
    --ui;
  else
    ++ui;
  return bitsToFloat(ui);
}

inline Float safeSqrt(Float x) { return std::sqrt(std::max(Float(0), x)); }
inline Float safeAcos(Float x) { return std::acos(clamp(x, -1, 1)); }
inline Float safeAsin(Float x) { return std::asin(clamp(x, -1, 1)); }

// Solves a t^2 + b t + c = 0 in double precision; t0 <= t1 (pbrt 3e §3.2.2).
inline bool solveQuadratic(double a, double b, double c, double* t0, double* t1) {
  double discrim = b * b - 4 * a * c;
  if (discrim < 0 || a == 0) return false;
  double root = std::sqrt(discrim);
  double q = (b < 0) ? -0.5 * (b - root) : -0.5 * (b + root);
  *t0 = q / a;
  *t1 = (q != 0) ? c / q : *t0;
  if (*t0 > *t1) std::swap(*t0, *t1);
  return true;
}

inline bool isPowerOf2(int v) { return v > 0 && (v & (v - 1)) == 0; }
inline int32_t roundUpPow2(int32_t v) {
  v--;
  v |= v >> 1;
  v |= v >> 2;
  v |= v >> 4;
  v |= v >> 8;
  v |= v >> 16;
  return v + 1;
}
inline int log2Int(uint32_t v) { return 31 - __builtin_clz(v); }

}  // namespace candela
