// Textures: values that vary over a surface (lrt draft ch. 11). Materials hold non-owning pointers;
// the scene owns every texture.
#pragma once

#include "core/interaction.h"
#include "core/spectrum.h"

namespace candela {

template <typename T>
class Texture {
 public:
  virtual ~Texture() = default;
  virtual T evaluate(const SurfaceInteraction& si) const = 0;
};

template <typename T>
class ConstantTexture : public Texture<T> {
 public:
  explicit ConstantTexture(const T& value) : value_(value) {}
  T evaluate(const SurfaceInteraction&) const override { return value_; }
  const T& value() const { return value_; }

 private:
  T value_;
};

}  // namespace candela
