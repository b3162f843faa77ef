// MIP maps (lrt draft §11.5.2-11.5.4): an image pyramid built once per image, filtered by
// trilinear interpolation (isotropic) or by elliptically weighted averaging (EWA, anisotropic).
//
// Pyramid: an image whose sides are not powers of two is first resampled up to the next powers
// of two with the draft's separable 4-tap Lanczos (windowed sinc, tau = 2) filter, each result
// clamped to the range of the texels it came from so that ringing never leaves the image's own
// range (a constant image stays exactly constant; pbrt-v2 clamps at 0 instead, which would break
// signed float images). Each coarser level is the box average of the 2x2 texels below it — all
// four of them (the draft's listing reads texel (2s+1, 2t) twice and never (2s+1, 2t+1)) — and of
// only the two that exist once one side is down to 1. Level 0 is the finest; the last is 1x1.
//
// Wrap modes apply to every texel read outside a level: "repeat" tiles, "clamp" extends the edge
// texels, "black" reads zero. The Lanczos resampling reads outside the image too; there "black"
// extends the edges like "clamp", since the resampled image covers the same [0, 1]^2.
//
// Texel (i, j) of a level of size w x h is centred at ((i + .5) / w, (j + .5) / h); row j = 0 is
// the first row of the texels given (image textures give the image's last row first, so t = 0 is
// at the bottom, as pbrt-v3: see bottomRowFirst).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/spectrum.h"
#include "core/vector.h"

namespace candela {

enum class WrapMode { Repeat, Black, Clamp };

// "repeat", "black", "clamp"; std::nullopt for anything else.
std::optional<WrapMode> parseWrapMode(const std::string& name);

template <typename T>
class MIPMap {
 public:
  using Value = T;
  // Largest side accepted (after rounding up to a power of two), so that texel coordinates of
  // lookups stay far inside the int range.
  static constexpr int kMaxResolution = 1 << 16;

  // texels: width * height values, row-major. Throws std::invalid_argument for an empty or
  // oversized image or a texel count that does not match.
  MIPMap(int width, int height, std::vector<T> texels, WrapMode wrap);

  int levels() const { return int(levels_.size()); }
  int levelWidth(int level) const { return levels_[size_t(level)].width; }
  int levelHeight(int level) const { return levels_[size_t(level)].height; }
  WrapMode wrapMode() const { return wrap_; }
  // Texel (s, t) of a level, any integers, through the wrap mode.
  T texel(int level, int s, int t) const;
  // The mean of the image: the single texel of the top level.
  T average() const { return levels_.back().texels[0]; }

  // Isotropic lookup over a square footprint of the given width in (s, t) (§11.5.3): bilinear
  // interpolation at the two levels whose texel spacing brackets the width, blended.
  T lookupTrilinear(Point2f st, Float width) const;
  // EWA lookup (§11.5.4) over the ellipse whose axes are the footprint vectors dst0 and dst1
  // (the (s, t) derivatives along screen x and y). maxAnisotropy bounds the ratio of the axes,
  // and so the number of texels read; it is clamped to [1, 64].
  T lookupEWA(Point2f st, Vector2f dst0, Vector2f dst1, Float maxAnisotropy) const;

 private:
  struct Level {
    int width, height;
    std::vector<T> texels;
  };
  std::vector<Level> levels_;
  WrapMode wrap_;
};

extern template class MIPMap<Float>;
extern template class MIPMap<Spectrum>;

}  // namespace candela
