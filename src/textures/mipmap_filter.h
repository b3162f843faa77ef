// The MIP map's filters (lrt draft §11.5.3-11.5.4), written against any pyramid P that offers
// Value, levels(), levelWidth(l), levelHeight(l), wrapMode() and texel(l, s, t) — MIPMap itself,
// or a test double that records every texel read.
//
// Robustness (seed inventory §23): non-finite (s, t) gives the image mean; NaN derivatives read
// as 0 (no footprint information: point sampling, as without ray differentials) and infinite
// ones as a footprint far wider than the texture. Coordinates are reduced before they become
// texel indices — by their fractional part for "repeat", by clamping to +-kMaxCoordinate for
// "black" and "clamp" (every footprint there is narrower than 65 texture units, so the result
// is unchanged) — so no float-to-int conversion overflows. The ellipse's eccentricity is bounded
// and its level chosen from its minor axis, so an EWA lookup reads at most about
// (4 maxAnisotropy + 3)^2 texels per level, however grazing the footprint.
#pragma once

#include <array>

#include "textures/mipmap.h"

namespace candela::mipmap_filter {

inline constexpr Float kMaxCoordinate = 1000;
inline constexpr Float kMaxFootprint = 1e4f;
inline constexpr Float kMaxAnisotropyLimit = 64;

// A texture coordinate reduced to where its texel indices are safe (see above); the caller has
// already rejected non-finite values.
inline Float reduceCoordinate(Float s, WrapMode wrap) {
  if (wrap == WrapMode::Repeat) return s - std::floor(s);
  return clamp(s, -kMaxCoordinate, kMaxCoordinate);
}

// A footprint derivative with NaN read as 0 and the magnitude bounded.
inline Float sanitizeDerivative(Float d) {
  if (std::isnan(d)) return 0;
  return clamp(d, -kMaxFootprint, kMaxFootprint);
}

// The EWA filter's Gaussian exp(-2 r^2), less its value at the ellipse's edge so the weight falls
// to zero there, tabulated over r^2 in [0, 1) (§11.5.4) at the middles of 128 bins.
inline Float ewaWeight(Float r2) {
  constexpr int kSize = 128;
  static const std::array<Float, kSize> table = [] {
    std::array<Float, kSize> t{};
    for (int i = 0; i < kSize; ++i)
      t[size_t(i)] = std::exp(-2 * (i + 0.5f) / kSize) - std::exp(-2.f);
    return t;
  }();
  return table[size_t(std::min(int(r2 * kSize), kSize - 1))];
}

template <typename P>
typename P::Value top(const P& p) {
  return p.texel(p.levels() - 1, 0, 0);
}

// Bilinear interpolation of the four texels around (s, t) at a level (the draft's triangle()).
template <typename P>
typename P::Value bilinear(const P& p, int level, Float s, Float t) {
  s = s * Float(p.levelWidth(level)) - 0.5f;
  t = t * Float(p.levelHeight(level)) - 0.5f;
  Float fs = std::floor(s), ft = std::floor(t);
  int s0 = int(fs), t0 = int(ft);
  Float ds = s - fs, dt = t - ft;
  return p.texel(level, s0, t0) * ((1 - ds) * (1 - dt)) +
         p.texel(level, s0, t0 + 1) * ((1 - ds) * dt) +
         p.texel(level, s0 + 1, t0) * (ds * (1 - dt)) + p.texel(level, s0 + 1, t0 + 1) * (ds * dt);
}

// §11.5.3: the level where the width spans one texel, log2 of the width below the top, blended
// between the two levels around it.
template <typename P>
typename P::Value trilinear(const P& p, Float s, Float t, Float width) {
  if (!std::isfinite(s) || !std::isfinite(t)) return top(p);
  s = reduceCoordinate(s, p.wrapMode());
  t = reduceCoordinate(t, p.wrapMode());
  width = std::abs(sanitizeDerivative(width));
  int nLevels = p.levels();
  Float level = Float(nLevels - 1) + std::log2(std::max(width, Float(1e-8)));
  if (level < 0) return bilinear(p, 0, s, t);
  if (level >= Float(nLevels - 1)) return top(p);
  int il = int(level);
  Float d = level - Float(il);
  return bilinear(p, il, s, t) * (1 - d) + bilinear(p, il + 1, s, t) * d;
}

// The Gaussian-weighted average over the ellipse with axes (ds0, dt0), (ds1, dt1) at one level.
template <typename P>
typename P::Value ewaAtLevel(const P& p, int level, Float s, Float t, Float ds0, Float dt0,
                             Float ds1, Float dt1) {
  using T = typename P::Value;
  if (level >= p.levels() - 1) return top(p);
  Float w = Float(p.levelWidth(level)), h = Float(p.levelHeight(level));
  s = s * w - 0.5f;
  t = t * h - 0.5f;
  ds0 *= w, ds1 *= w, dt0 *= h, dt1 *= h;
  // The ellipse x^T M^-1 x < 1 for M = J J^T + I, J's columns the axes: the identity keeps it at
  // least one texel wide, so it never falls between texels when magnifying (§11.5.4, note 3).
  Float a = dt0 * dt0 + dt1 * dt1 + 1;
  Float b = -2 * (ds0 * dt0 + ds1 * dt1);
  Float c = ds0 * ds0 + ds1 * ds1 + 1;
  Float invF = 1 / (a * c - b * b * 0.25f);
  a *= invF, b *= invF, c *= invF;
  // Half-extents of the ellipse's bounding box: sqrt of M's diagonal. The cap is never reached
  // when the axes come from lookupEWA (at most 2 * 64 texels long); it bounds the loop anyway.
  Float det = 4 * a * c - b * b;
  constexpr Float kMaxHalfExtent = 2 * kMaxAnisotropyLimit + 4;
  Float sr = std::min(2 * std::sqrt(c / det), kMaxHalfExtent);
  Float tr = std::min(2 * std::sqrt(a / det), kMaxHalfExtent);
  int s0 = int(std::ceil(s - sr)), s1 = int(std::floor(s + sr));
  int t0 = int(std::ceil(t - tr)), t1 = int(std::floor(t + tr));
  T sum(0);
  Float weightSum = 0;
  for (int it = t0; it <= t1; ++it) {
    Float tt = Float(it) - t;
    for (int is = s0; is <= s1; ++is) {
      Float ss = Float(is) - s;
      Float r2 = a * ss * ss + b * ss * tt + c * tt * tt;
      if (r2 < 1) {
        Float wt = ewaWeight(r2);
        sum += p.texel(level, is, it) * wt;
        weightSum += wt;
      }
    }
  }
  // The nearest texel is always inside (r^2 <= 1/2), so the sum has weight; guard regardless.
  if (!(weightSum > 0)) return p.texel(level, int(std::floor(s + 0.5f)), int(std::floor(t + 0.5f)));
  return sum * (1 / weightSum);
}

// §11.5.4: order the axes, bound the eccentricity by growing the minor axis, choose the level
// where the minor axis spans about one texel, and blend the EWA results of the two levels
// around it (pbrt-v2's refinement of the draft's single level).
template <typename P>
typename P::Value ewa(const P& p, Float s, Float t, Float ds0, Float dt0, Float ds1, Float dt1,
                      Float maxAnisotropy) {
  if (!std::isfinite(s) || !std::isfinite(t)) return top(p);
  s = reduceCoordinate(s, p.wrapMode());
  t = reduceCoordinate(t, p.wrapMode());
  ds0 = sanitizeDerivative(ds0), dt0 = sanitizeDerivative(dt0);
  ds1 = sanitizeDerivative(ds1), dt1 = sanitizeDerivative(dt1);
  maxAnisotropy = std::isnan(maxAnisotropy) ? 1 : clamp(maxAnisotropy, 1, kMaxAnisotropyLimit);
  if (ds0 * ds0 + dt0 * dt0 < ds1 * ds1 + dt1 * dt1) {
    std::swap(ds0, ds1);
    std::swap(dt0, dt1);
  }
  Float major = std::sqrt(ds0 * ds0 + dt0 * dt0), minor = std::sqrt(ds1 * ds1 + dt1 * dt1);
  if (major == 0) return bilinear(p, 0, s, t);
  if (minor * maxAnisotropy < major) {
    if (minor > 0) {
      Float scale = major / (minor * maxAnisotropy);
      ds1 *= scale, dt1 *= scale;
    } else {
      // A footprint collapsed to a line: pbrt-v2 point-samples it, which aliases; widen it
      // perpendicular to the major axis instead.
      ds1 = -dt0 / maxAnisotropy, dt1 = ds0 / maxAnisotropy;
    }
    minor = major / maxAnisotropy;
  }
  int nLevels = p.levels();
  Float lod = std::max(Float(0), Float(nLevels - 1) + std::log2(minor));
  if (lod >= Float(nLevels - 1)) return top(p);
  int il = int(lod);
  Float d = lod - Float(il);
  auto at = [&](int level) { return ewaAtLevel(p, level, s, t, ds0, dt0, ds1, dt1); };
  if (d == 0) return at(il);
  return at(il) * (1 - d) + at(il + 1) * d;
}

}  // namespace candela::mipmap_filter
