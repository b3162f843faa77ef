// Solid textures built on noise (lrt draft §11.7.3-11.7.6): fbm ("bumpy" in the draft), wrinkled
// (turbulence), windy waves and marble, with pbrt-v2's parameters. The float-valued ones also
// exist as grey spectra, as in pbrt-v2. All are antialiased by clamping the octave count to the
// footprint (§11.7.3).
#pragma once

#include "textures/mapping.h"
#include "textures/noise.h"
#include "textures/texture.h"

namespace candela {

// FBm(p) with octaves and roughness omega.
template <typename T>
class FBmTexture : public Texture<T> {
 public:
  FBmTexture(TextureMapping3D mapping, int octaves, Float omega)
      : mapping_(std::move(mapping)), octaves_(octaves), omega_(omega) {}
  T evaluate(const SurfaceInteraction& si) const override {
    TexCoord3D c = mapping_.map(si);
    return T(fbm(c.p, c.dpdx, c.dpdy, omega_, octaves_));
  }

 private:
  TextureMapping3D mapping_;
  int octaves_;
  Float omega_;
};

// Turbulence(p): sharp creases where noise crosses zero.
template <typename T>
class WrinkledTexture : public Texture<T> {
 public:
  WrinkledTexture(TextureMapping3D mapping, int octaves, Float omega,
                  ClampedOctaves clamped = ClampedOctaves::Mean)
      : mapping_(std::move(mapping)), octaves_(octaves), omega_(omega), clamped_(clamped) {}
  T evaluate(const SurfaceInteraction& si) const override {
    TexCoord3D c = mapping_.map(si);
    return T(turbulence(c.p, c.dpdx, c.dpdy, omega_, octaves_, clamped_));
  }

 private:
  TextureMapping3D mapping_;
  int octaves_;
  Float omega_;
  ClampedOctaves clamped_;
};

// Waves on wind-swept water (§11.7.6): a low-frequency FBm (p / 10, 3 octaves) sets the local
// wind strength, a 6-octave FBm the wave; their product is the height.
template <typename T>
class WindyTexture : public Texture<T> {
 public:
  explicit WindyTexture(TextureMapping3D mapping) : mapping_(std::move(mapping)) {}
  T evaluate(const SurfaceInteraction& si) const override {
    TexCoord3D c = mapping_.map(si);
    Float wind = fbm(c.p * 0.1f, c.dpdx * 0.1f, c.dpdy * 0.1f, 0.5f, 3);
    Float wave = fbm(c.p, c.dpdx, c.dpdy, 0.5f, 6);
    return T(std::abs(wind) * wave);
  }

 private:
  TextureMapping3D mapping_;
};

// Marble (§11.7.5) with pbrt-v2's parameters: p is scaled by `scale`, perturbed along y by
// variation * FBm, and t = .5 + .5 sin(p.y') indexes a cubic Bezier spline through fixed stone
// colours, scaled by 1.5 (pbrt-v2's form; the draft fixes scale .05 and uses |sin(5 marble)|).
// Deliberately not pbrt-v3's: it picks the spline segment as min(1, floor(6t)), so for t > 1/3 it
// extrapolates the cubic far outside the table (reflectances up to about 40; pbrt-v3 issue #252).
// Its renders of marble are brighter, with overexposed bands; with its segment rule ours agree.
class MarbleTexture : public Texture<Spectrum> {
 public:
  MarbleTexture(TextureMapping3D mapping, int octaves, Float omega, Float scale, Float variation)
      : mapping_(std::move(mapping)),
        octaves_(octaves),
        omega_(omega),
        scale_(scale),
        variation_(variation) {}
  Spectrum evaluate(const SurfaceInteraction& si) const override;

 private:
  TextureMapping3D mapping_;
  int octaves_;
  Float omega_, scale_, variation_;
};

}  // namespace candela
