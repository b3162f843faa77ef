#include <array>

#include "textures/solid_textures.h"

namespace candela {

Spectrum MarbleTexture::evaluate(const SurfaceInteraction& si) const {
  TexCoord3D c = mapping_.map(si);
  Point3f p = c.p * scale_;
  Float marble = p.y + variation_ * fbm(p, c.dpdx * scale_, c.dpdy * scale_, omega_, octaves_);
  Float t = Float(0.5) + Float(0.5) * std::sin(marble);
  if (!std::isfinite(t)) t = 0.5f;

  // pbrt-v2's control colours: grey stone with a dark blue-grey vein.
  static constexpr std::array<Spectrum, 9> kColors = {
      Spectrum(.58f, .58f, .6f), Spectrum(.58f, .58f, .6f), Spectrum(.58f, .58f, .6f),
      Spectrum(.5f, .5f, .5f),   Spectrum(.6f, .59f, .58f), Spectrum(.58f, .58f, .6f),
      Spectrum(.58f, .58f, .6f), Spectrum(.2f, .2f, .33f),  Spectrum(.58f, .58f, .6f)};
  constexpr int kSegments = int(kColors.size()) - 3;
  // Segment i uses control points i..i+3; t = 1 (sin = 1) belongs to the last segment (the
  // book's code reads past the table there).
  int first = std::min(int(t * kSegments), kSegments - 1);
  Float u = t * kSegments - Float(first);
  // De Casteljau evaluation of the cubic Bezier segment.
  Spectrum c0 = kColors[first], c1 = kColors[first + 1], c2 = kColors[first + 2],
           c3 = kColors[first + 3];
  Spectrum s0 = c0 * (1 - u) + c1 * u, s1 = c1 * (1 - u) + c2 * u, s2 = c2 * (1 - u) + c3 * u;
  s0 = s0 * (1 - u) + s1 * u;
  s1 = s1 * (1 - u) + s2 * u;
  return (s0 * (1 - u) + s1 * u) * Float(1.5);
}

}  // namespace candela
