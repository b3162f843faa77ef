// The simple textures of lrt draft §11.1, §11.4 and §11.6.1: products, blends, bilinear
// interpolation and the (u, v) debugging texture. None of them filters: each is as smooth as its
// inputs (§11.4). Sub-textures are owned by the TextureFactory.
#pragma once

#include <memory>

#include "textures/mapping.h"
#include "textures/texture.h"

namespace candela {

// tex1 * tex2 (pbrt-v2 "scale").
template <typename T>
class ScaleTexture : public Texture<T> {
 public:
  ScaleTexture(const Texture<T>* tex1, const Texture<T>* tex2) : tex1_(tex1), tex2_(tex2) {}
  T evaluate(const SurfaceInteraction& si) const override {
    return tex1_->evaluate(si) * tex2_->evaluate(si);
  }

 private:
  const Texture<T>* tex1_;
  const Texture<T>* tex2_;
};

// (1 - amount) tex1 + amount tex2; amount is not clamped, so it may extrapolate (§11.1.3).
template <typename T>
class MixTexture : public Texture<T> {
 public:
  MixTexture(const Texture<T>* tex1, const Texture<T>* tex2, const Texture<Float>* amount)
      : tex1_(tex1), tex2_(tex2), amount_(amount) {}
  T evaluate(const SurfaceInteraction& si) const override {
    Float a = amount_->evaluate(si);
    return tex1_->evaluate(si) * (1 - a) + tex2_->evaluate(si) * a;
  }

 private:
  const Texture<T>* tex1_;
  const Texture<T>* tex2_;
  const Texture<Float>* amount_;
};

// Bilinear interpolation of the corner values v00 (s = t = 0), v01 (t = 1), v10 (s = 1) and v11
// at the mapped (s, t) (§11.4.1); outside [0, 1]^2 it extrapolates, as the draft's formula does.
template <typename T>
class BilerpTexture : public Texture<T> {
 public:
  BilerpTexture(std::unique_ptr<TextureMapping2D> mapping, const T& v00, const T& v01, const T& v10,
                const T& v11)
      : mapping_(std::move(mapping)), v00_(v00), v01_(v01), v10_(v10), v11_(v11) {}
  T evaluate(const SurfaceInteraction& si) const override {
    Point2f st = mapping_->map(si).st;
    Float s = st.x, t = st.y;
    return v00_ * ((1 - s) * (1 - t)) + v01_ * ((1 - s) * t) + v10_ * (s * (1 - t)) +
           v11_ * (s * t);
  }

 private:
  std::unique_ptr<TextureMapping2D> mapping_;
  T v00_, v01_, v10_, v11_;
};

// (frac(s), frac(t), 0) as a colour (§11.6.1), for looking at a parameterization. The fractional
// part is pbrt-v2's; the draft returns s and t unwrapped.
class UVTexture : public Texture<Spectrum> {
 public:
  explicit UVTexture(std::unique_ptr<TextureMapping2D> mapping) : mapping_(std::move(mapping)) {}
  Spectrum evaluate(const SurfaceInteraction& si) const override {
    Point2f st = mapping_->map(si).st;
    return Spectrum(st.x - std::floor(st.x), st.y - std::floor(st.y), 0);
  }

 private:
  std::unique_ptr<TextureMapping2D> mapping_;
};

}  // namespace candela
