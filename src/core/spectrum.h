// Colour as RGB in the scene-linear space (linear Rec.709 primaries, D65 white by default). The
// seeds' Spectrum with COLOR_SAMPLES = 3 (lrt draft §5.1); spectral inputs are converted to this
// space when the scene is read.
#pragma once

#include <ostream>

#include "core/common.h"

namespace candela {

class Spectrum {
 public:
  Spectrum() = default;
  explicit constexpr Spectrum(Float v) : c_{v, v, v} {}
  constexpr Spectrum(Float r, Float g, Float b) : c_{r, g, b} {}

  Float operator[](int i) const { return c_[i]; }
  Float& operator[](int i) { return c_[i]; }
  Float r() const { return c_[0]; }
  Float g() const { return c_[1]; }
  Float b() const { return c_[2]; }

  Spectrum operator+(const Spectrum& s) const { return {c_[0] + s[0], c_[1] + s[1], c_[2] + s[2]}; }
  Spectrum& operator+=(const Spectrum& s) {
    for (int i = 0; i < 3; ++i) c_[i] += s[i];
    return *this;
  }
  Spectrum operator-(const Spectrum& s) const { return {c_[0] - s[0], c_[1] - s[1], c_[2] - s[2]}; }
  Spectrum operator*(const Spectrum& s) const { return {c_[0] * s[0], c_[1] * s[1], c_[2] * s[2]}; }
  Spectrum& operator*=(const Spectrum& s) {
    for (int i = 0; i < 3; ++i) c_[i] *= s[i];
    return *this;
  }
  Spectrum operator*(Float a) const { return {c_[0] * a, c_[1] * a, c_[2] * a}; }
  Spectrum& operator*=(Float a) {
    for (int i = 0; i < 3; ++i) c_[i] *= a;
    return *this;
  }
  Spectrum operator/(const Spectrum& s) const {
    return {s[0] != 0 ? c_[0] / s[0] : 0, s[1] != 0 ? c_[1] / s[1] : 0,
            s[2] != 0 ? c_[2] / s[2] : 0};
  }
  Spectrum operator/(Float a) const { return *this * (Float(1) / a); }
  Spectrum& operator/=(Float a) { return *this *= (Float(1) / a); }
  Spectrum operator-() const { return {-c_[0], -c_[1], -c_[2]}; }
  bool operator==(const Spectrum& s) const {
    return c_[0] == s[0] && c_[1] == s[1] && c_[2] == s[2];
  }
  bool operator!=(const Spectrum& s) const { return !(*this == s); }

  // Every channel +-0 (NaN is not black). Tested on the bits, whose magnitude parts are then all
  // zero: the three float comparisons, each with its unordered case, took ~18 instructions.
  bool isBlack() const {
    return ((floatToBits(c_[0]) | floatToBits(c_[1]) | floatToBits(c_[2])) << 1) == 0;
  }
  bool hasNaN() const { return std::isnan(c_[0]) || std::isnan(c_[1]) || std::isnan(c_[2]); }
  bool isFinite() const {
    return std::isfinite(c_[0]) && std::isfinite(c_[1]) && std::isfinite(c_[2]);
  }
  Float maxComponent() const { return std::max(c_[0], std::max(c_[1], c_[2])); }
  Float average() const { return (c_[0] + c_[1] + c_[2]) / 3; }
  // Luminance Y of linear Rec.709 RGB.
  Float y() const { return 0.212671f * c_[0] + 0.715160f * c_[1] + 0.072169f * c_[2]; }

  // CIE XYZ to linear Rec.709 RGB (lrt draft §5.2.2's matrix).
  static Spectrum fromXYZ(Float x, Float y, Float z) {
    return {3.240479f * x - 1.537150f * y - 0.498535f * z,
            -0.969256f * x + 1.875991f * y + 0.041556f * z,
            0.055648f * x - 0.204043f * y + 1.057311f * z};
  }
  void toXYZ(Float xyz[3]) const {
    xyz[0] = 0.412453f * c_[0] + 0.357580f * c_[1] + 0.180423f * c_[2];
    xyz[1] = y();
    xyz[2] = 0.019334f * c_[0] + 0.119193f * c_[1] + 0.950227f * c_[2];
  }

 private:
  Float c_[3] = {0, 0, 0};
};

inline Spectrum operator*(Float a, const Spectrum& s) { return s * a; }
inline Spectrum sqrt(const Spectrum& s) {
  return {std::sqrt(s[0]), std::sqrt(s[1]), std::sqrt(s[2])};
}
inline Spectrum exp(const Spectrum& s) { return {std::exp(s[0]), std::exp(s[1]), std::exp(s[2])}; }
inline Spectrum clampSpectrum(const Spectrum& s, Float lo = 0, Float hi = kInfinity) {
  return {clamp(s[0], lo, hi), clamp(s[1], lo, hi), clamp(s[2], lo, hi)};
}
inline std::ostream& operator<<(std::ostream& os, const Spectrum& s) {
  return os << "rgb(" << s[0] << ", " << s[1] << ", " << s[2] << ")";
}

}  // namespace candela
