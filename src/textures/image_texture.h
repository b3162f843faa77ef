// Image textures (lrt draft §11.5): an image in scene-linear colour, MIP-mapped, looked up at the
// mapped (s, t) with EWA filtering (default) or trilinear filtering. The TextureFactory loads each
// file once and shares the pyramid between textures that read it the same way (§11.5.1's cache,
// owned by the render job instead of a static map).
#pragma once

#include <memory>

#include "core/image_buffer.h"
#include "textures/mapping.h"
#include "textures/mipmap.h"
#include "textures/texture.h"

namespace candela {

// The texels of a scene-linear image with pbrt-v2's adjustment v' = (scale v)^gamma applied per
// channel (gamma 1 leaves v unchanged; otherwise negative values become 0 first). Channels R, G, B
// are found by name, else the first three are used; a one- or two-channel image is grey (its
// first channel). Float texels are the luminance of the RGB, computed before scale and gamma (as
// pbrt-v2). The image's first row becomes texel row 0 (see bottomRowFirst).
std::vector<Spectrum> spectrumTexels(const ImageBuffer& image, Float scale, Float gamma);
std::vector<Float> floatTexels(const ImageBuffer& image, Float scale, Float gamma);

// The rows of a width-wide image in reverse order. Image textures of pbrt-v3 scenes read their
// texels so, since pbrt-v3 puts (s, t) = (0, 0) at the image's lower left corner (pbrt-v2 at its
// upper left).
template <typename T>
std::vector<T> bottomRowFirst(const std::vector<T>& texels, int width) {
  std::vector<T> flipped;
  flipped.reserve(texels.size());
  for (size_t end = texels.size(); end >= size_t(width) && width > 0; end -= size_t(width))
    flipped.insert(flipped.end(), texels.begin() + std::ptrdiff_t(end - size_t(width)),
                   texels.begin() + std::ptrdiff_t(end));
  return flipped;
}

template <typename T>
class ImageTexture : public Texture<T> {
 public:
  ImageTexture(std::unique_ptr<TextureMapping2D> mapping, std::shared_ptr<const MIPMap<T>> mipmap,
               bool trilinear, Float maxAnisotropy)
      : mapping_(std::move(mapping)),
        mipmap_(std::move(mipmap)),
        trilinear_(trilinear),
        maxAnisotropy_(maxAnisotropy) {}

  T evaluate(const SurfaceInteraction& si) const override {
    TexCoord2D c = mapping_->map(si);
    if (trilinear_) {
      // A square covering the whole footprint (pbrt-v2): twice the largest derivative.
      Float width = 2 * std::max(std::max(std::abs(c.dsdx), std::abs(c.dtdx)),
                                 std::max(std::abs(c.dsdy), std::abs(c.dtdy)));
      return mipmap_->lookupTrilinear(c.st, width);
    }
    return mipmap_->lookupEWA(c.st, Vector2f(c.dsdx, c.dtdx), Vector2f(c.dsdy, c.dtdy),
                              maxAnisotropy_);
  }
  const MIPMap<T>& mipmap() const { return *mipmap_; }

 private:
  std::unique_ptr<TextureMapping2D> mapping_;
  std::shared_ptr<const MIPMap<T>> mipmap_;
  bool trilinear_;
  Float maxAnisotropy_;
};

}  // namespace candela
