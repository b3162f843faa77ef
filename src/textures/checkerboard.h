// Checkerboards (lrt draft §11.6.2-11.6.3): tex1 where floor(s) + floor(t) is even, tex2 where it
// is odd, with unit checks in (s, t) (scale them with the mapping); and the solid version on
// floor(x) + floor(y) + floor(z). Antialiasing modes:
//   "closedform" (2D default): the box-filtered average over the footprint's bounding box,
//     computed from the integral of the 1D check function; a footprint inside one check
//     evaluates only that check's texture, one wider than two checks gives the 50% mix;
//   "supersample": 16 stratified samples (4x4) over the footprint, Gaussian weighted, each
//     evaluating its check's texture at a shifted interaction with footprints shrunk by 4 (so
//     nested textures filter correctly, §11.6.2, figure 11.19). The jitter comes from a hash of
//     the shading point rather than a random number generator, so an image stays a pure function
//     of the scene and seed (an unjittered grid aliases: at 8 checks per pixel all 16 samples
//     would land on the same colour);
//   "none": point sampling.
// The solid checkerboard takes "none" or "supersample" (its default, as the draft's §11.6.3; a
// 3D closed form does not exist, so "closedform" selects supersampling there).
#pragma once

#include <memory>

#include "textures/mapping.h"
#include "textures/texture.h"

namespace candela {

enum class CheckerboardAA { None, ClosedForm, Supersample };

// True where the check at (s, t) is tex2's (floor(s) + floor(t) odd).
bool checkIsTex2(Float s, Float t);
bool checkIsTex2(const Point3f& p);

// The fraction of the box [s - ds, s + ds] x [t - dt, t + dt] covered by tex2's checks (the
// closed form of §11.6.2): exactly 0 or 1 when the box is inside one check, 0.5 when it is
// wider than two checks. ds, dt >= 0; non-finite (s, t) gives 0.5.
Float checkerboardTex2Fraction(Float s, Float t, Float ds, Float dt);

// si moved by (dx, dy) pixels along its screen-space differentials (the draft's
// DifferentialGeometry::Shift, assuming the surface is locally flat), with all differentials
// multiplied by shrink.
SurfaceInteraction shiftedInteraction(const SurfaceInteraction& si, Float dx, Float dy,
                                      Float shrink);

// A deterministic jitter in [0, 1)^2 for sample `index` at si: a hash of si's position.
Point2f supersampleJitter(const SurfaceInteraction& si, int index);

// The supersampled checkerboard: isTex2(shifted interaction) decides each sample's texture.
template <typename T, typename IsTex2>
T supersampleChecks(const SurfaceInteraction& si, const Texture<T>& tex1, const Texture<T>& tex2,
                    IsTex2 isTex2) {
  constexpr int kN = 4;
  T sum(0);
  Float weightSum = 0;
  for (int j = 0; j < kN; ++j)
    for (int i = 0; i < kN; ++i) {
      Point2f jitter = supersampleJitter(si, j * kN + i);
      Float dx = (i + jitter.x) / kN - Float(0.5), dy = (j + jitter.y) / kN - Float(0.5);
      SurfaceInteraction shifted = shiftedInteraction(si, dx, dy, Float(1) / kN);
      Float w = std::exp(-2 * (dx * dx + dy * dy));
      sum += (isTex2(shifted) ? tex2 : tex1).evaluate(shifted) * w;
      weightSum += w;
    }
  return sum * (1 / weightSum);
}

template <typename T>
class Checkerboard2DTexture : public Texture<T> {
 public:
  Checkerboard2DTexture(std::unique_ptr<TextureMapping2D> mapping, const Texture<T>* tex1,
                        const Texture<T>* tex2, CheckerboardAA aa)
      : mapping_(std::move(mapping)), tex1_(tex1), tex2_(tex2), aa_(aa) {}

  T evaluate(const SurfaceInteraction& si) const override {
    TexCoord2D c = mapping_->map(si);
    if (aa_ == CheckerboardAA::Supersample)
      return supersampleChecks(si, *tex1_, *tex2_, [this](const SurfaceInteraction& s) {
        Point2f st = mapping_->map(s).st;
        return checkIsTex2(st.x, st.y);
      });
    if (aa_ == CheckerboardAA::None)
      return (checkIsTex2(c.st.x, c.st.y) ? tex2_ : tex1_)->evaluate(si);
    // Half the distance to the neighbouring samples each way: the pixel's own footprint.
    Float ds = Float(0.5) * std::max(magnitude(c.dsdx), magnitude(c.dsdy));
    Float dt = Float(0.5) * std::max(magnitude(c.dtdx), magnitude(c.dtdy));
    Float f = checkerboardTex2Fraction(c.st.x, c.st.y, ds, dt);
    if (f == 0) return tex1_->evaluate(si);
    if (f == 1) return tex2_->evaluate(si);
    return tex1_->evaluate(si) * (1 - f) + tex2_->evaluate(si) * f;
  }

 private:
  // |v|, with NaN (an unknown footprint) read as 0: point sampling, as without differentials.
  static Float magnitude(Float v) { return std::isnan(v) ? 0 : std::abs(v); }

  std::unique_ptr<TextureMapping2D> mapping_;
  const Texture<T>* tex1_;
  const Texture<T>* tex2_;
  CheckerboardAA aa_;
};

template <typename T>
class Checkerboard3DTexture : public Texture<T> {
 public:
  Checkerboard3DTexture(TextureMapping3D mapping, const Texture<T>* tex1, const Texture<T>* tex2,
                        bool supersample)
      : mapping_(std::move(mapping)), tex1_(tex1), tex2_(tex2), supersample_(supersample) {}

  T evaluate(const SurfaceInteraction& si) const override {
    if (supersample_)
      return supersampleChecks(si, *tex1_, *tex2_, [this](const SurfaceInteraction& s) {
        return checkIsTex2(mapping_.map(s).p);
      });
    return (checkIsTex2(mapping_.map(si).p) ? tex2_ : tex1_)->evaluate(si);
  }

 private:
  TextureMapping3D mapping_;
  const Texture<T>* tex1_;
  const Texture<T>* tex2_;
  bool supersample_;
};

}  // namespace candela
