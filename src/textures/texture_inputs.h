// What a texture class's create function (textures/texture_plugins.h) builds from: the Texture
// statement's parameters, the textures they name, and the images they read. The build implements
// it (assembly/texture_factory.h: graphics-state scoping of names, one load per image, one MIP map
// per image and filter settings), so texture plug-ins need neither the parser nor the factories.
#pragma once

#include <memory>
#include <string>
#include <type_traits>

#include "core/paramset.h"
#include "core/transform.h"
#include "textures/mipmap.h"
#include "textures/noise.h"
#include "textures/texture_lookup.h"

namespace candela {

class TextureInputs : public TextureLookup {
 public:
  virtual const ParamSet& params() const = 0;
  virtual const FileLoc& location() const = 0;
  virtual const std::string& textureName() const = 0;  // the statement's, for messages
  // The CTM at the Texture statement.
  virtual const Transform& textureToWorld() const = 0;
  // What the octaves a wrinkled texture's footprint drops contribute (the compatibility profile).
  virtual ClampedOctaves clampedOctaves() const = 0;
  // The MIP map of the image at path (colour space as ImageLoader's), read and built once per
  // (path, colour space, wrap, scale, gamma) and type, its rows in the order the scene's dialect
  // wants. SceneError naming this texture and the path when unreadable.
  virtual std::shared_ptr<const MIPMap<Float>> floatMipmap(const std::string& path,
                                                           const std::string& colorSpace,
                                                           WrapMode wrap, Float scale,
                                                           Float gamma) = 0;
  virtual std::shared_ptr<const MIPMap<Spectrum>> spectrumMipmap(const std::string& path,
                                                                 const std::string& colorSpace,
                                                                 WrapMode wrap, Float scale,
                                                                 Float gamma) = 0;

  // The two above for a texture of type T.
  template <typename T>
  const Texture<T>* texture(const std::string& name, const T& def) {
    if constexpr (std::is_same_v<T, Float>)
      return scalar(name, def);
    else
      return spectrum(name, def);
  }
  template <typename T>
  std::shared_ptr<const MIPMap<T>> mipmap(const std::string& path, const std::string& colorSpace,
                                          WrapMode wrap, Float scale, Float gamma) {
    if constexpr (std::is_same_v<T, Float>)
      return floatMipmap(path, colorSpace, wrap, scale, gamma);
    else
      return spectrumMipmap(path, colorSpace, wrap, scale, gamma);
  }
};

}  // namespace candela
