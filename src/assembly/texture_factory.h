// Creates the textures that materials name, once each and only when used (DESIGN.md, data flow
// step 2), and turns a material parameter into a texture: a "texture" reference or a constant.
//
// Texture classes: the textures' table (textures/texture_plugins.cpp: pbrt-v2's names, parameters
// and defaults), through which create() dispatches; each class's create function reads its
// statement through a TextureInputs this factory implements.
// A name in a texture's, material's or shape's parameters means the definition bound to it at
// that statement (PluginDesc::textures, from SceneBuilder: pbrt's graphics-state scoping), so a
// texture only ever names earlier textures and references cannot form a cycle. Descriptions
// without bindings (made by hand) read a name as its latest definition before the texture, or the
// latest of all for a material.
//
// Image textures read their files through the ImageLoader (core/image_loader.h), one load per
// (path, colour space) however many textures use it, and one MIP map per (path, colour space, wrap,
// scale, gamma, float/spectrum). Relative filenames resolve against the directory of the scene file
// holding the Texture statement. A missing or unreadable file is an error naming the path (pbrt-v2
// warned and used a constant); an image texture no material uses is never loaded.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "core/image_loader.h"
#include "parser/scene_description.h"
#include "textures/mipmap.h"
#include "textures/noise.h"
#include "textures/texture.h"

namespace candela {

class TextureFactory {
 public:
  using Warn = std::function<void(const FileLoc&, const std::string&)>;

  // Where an image texture's t = 0 lies: pbrt-v3 puts (s, t) = (0, 0) at the image's lower left
  // corner, pbrt-v2 and the lrt draft at its upper left (parser/scene_dialect.h decides).
  enum class ImageOrigin { BottomLeft, TopLeft };

  // clampedOctaves: what the octaves a wrinkled texture's footprint drops contribute.
  explicit TextureFactory(const std::vector<TextureDesc>& descs, ImageLoader loadImage = {},
                          Warn warn = {}, ImageOrigin imageOrigin = ImageOrigin::BottomLeft,
                          ClampedOctaves clampedOctaves = ClampedOctaves::Mean);
  ~TextureFactory();
  TextureFactory(const TextureFactory&) = delete;
  TextureFactory& operator=(const TextureFactory&) = delete;

  // The parameter `name` as a texture: the named texture when the item is a "texture" reference,
  // else a constant of the given value (or def when absent). Throws SceneError for a missing
  // texture, one of the other type, an unknown class or bad parameters.
  const Texture<Spectrum>* spectrum(const ParamSet& params, const std::string& name,
                                    const Spectrum& def, const FileLoc& loc,
                                    const TextureBindings* bindings = nullptr);
  const Texture<Float>* scalar(const ParamSet& params, const std::string& name, Float def,
                               const FileLoc& loc, const TextureBindings* bindings = nullptr);
  // The same for a statement's parameters, with the names bound at that statement.
  const Texture<Spectrum>* spectrum(const PluginDesc& d, const std::string& name,
                                    const Spectrum& def) {
    return spectrum(d.params, name, def, d.loc, d.textures ? &*d.textures : nullptr);
  }
  const Texture<Float>* scalar(const PluginDesc& d, const std::string& name, Float def) {
    return scalar(d.params, name, def, d.loc, d.textures ? &*d.textures : nullptr);
  }

  // Keeps t alive as long as the textures made here (a texture built from made ones).
  template <typename T>
  const Texture<T>* adopt(std::unique_ptr<Texture<T>> t) {
    store<T>().owned.push_back(std::move(t));
    return store<T>().owned.back().get();
  }

  int texturesCreated() const { return created_; }  // named textures (not inline constants)
  int imagesLoaded() const { return imagesLoaded_; }
  int mipmapsBuilt() const { return mipmapsBuilt_; }
  // Frees the decoded images kept to build further MIP maps from; call once every material is
  // made (a later image texture would read its file again).
  void releaseImages() { images_.clear(); }

 private:
  using MipKey = std::tuple<std::string, std::string, WrapMode, Float, Float>;
  ImageOrigin imageOrigin_;
  ClampedOctaves clampedOctaves_;
  template <typename T>
  struct Store {
    std::map<size_t, const Texture<T>*> byIndex;  // named textures by their TextureDesc
    std::vector<std::unique_ptr<Texture<T>>> owned;
    std::map<MipKey, std::shared_ptr<const MIPMap<T>>> mipmaps;
  };
  template <typename T>
  Store<T>& store();
  class Inputs;  // the TextureInputs of one statement

  // Without bindings, textures may only name textures defined before index `visible` (see above).
  template <typename T>
  const Texture<T>* parameter(const ParamSet& params, const std::string& name, const T& def,
                              const FileLoc& loc, size_t visible, const TextureBindings* bindings);
  template <typename T>
  const Texture<T>* named(size_t index);
  template <typename T>
  std::unique_ptr<Texture<T>> create(const TextureDesc& d, size_t index);
  template <typename T>
  std::shared_ptr<const MIPMap<T>> mipmap(const std::string& path, const std::string& colorSpace,
                                          WrapMode wrap, Float scale, Float gamma,
                                          const TextureDesc& d);
  std::optional<size_t> find(const std::string& textureName, const std::string& type,
                             size_t visible, const TextureBindings* bindings) const;
  const ImageBuffer& image(const std::string& path, const std::string& colorSpace,
                           const TextureDesc& d);

  const std::vector<TextureDesc>& descs_;
  ImageLoader loadImage_;
  Warn warn_;
  Store<Spectrum> spectra_;
  Store<Float> floats_;
  std::map<std::pair<std::string, std::string>, ImageBuffer> images_;
  int created_ = 0, imagesLoaded_ = 0, mipmapsBuilt_ = 0;
  int nesting_ = 0;  // textures being created, each inside the one before (see named())
};

}  // namespace candela
